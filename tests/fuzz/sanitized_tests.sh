#!/usr/bin/env bash
# Runs the parsers' and the command line's unit tests built with AddressSanitizer (LeakSanitizer included) and
# UndefinedBehaviorSanitizer: the test binary's `scenes` and `cli` modules (JSON scenes, glTF import, EXR maps,
# PNG frames, textures, every command end to end through the instrumented `shadowlab` executable), compiled in
# the fuzz build directory, whose libraries already carry the instrumentation (tests/fuzz/run.sh builds them).
#   tests/fuzz/sanitized_tests.sh [GTEST_FILTER]
# Build directory: SHADOWLAB_FUZZ_BUILD (default build-fuzz in the repository). The whole unit-test binary under
# the sanitizers does not fit beside the Release suite in CI's 90 minutes on two cores (docs/fuzzing.md has the
# figures); the rasterizer's own modules are exercised under the sanitizers by the whole-scene fuzz targets.
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${SHADOWLAB_FUZZ_BUILD:-$root/build-fuzz}
filter=${1:-*}

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DSHADOWLAB_FUZZ=ON -DSHADOWLAB_TESTS=ON -DSHADOWLAB_TEST_MODULES="scenes;cli" -DSHADOWLAB_BENCH=OFF \
  -DSHADOWLAB_GL_REFERENCE=OFF >/dev/null || exit 2
mkdir -p "$build/fuzz-logs"
cmake --build "$build" --parallel "$(nproc)" --target shadowlab shadowlab_tests >"$build/fuzz-logs/tests-build.log" 2>&1 || {
  grep -a -E 'error|FAILED|undefined reference' "$build/fuzz-logs/tests-build.log" | head -20 | sed 's/^/  /' >&2
  echo "shadowlab sanitized tests: building failed (log: $build/fuzz-logs/tests-build.log;" \
    "run: cmake --build $build --target shadowlab_tests)" >&2
  exit 2
}
# The same leak suppressions as the fuzzers (third-party leaks our code cannot free, each explained there); a
# sanitizer report ends the test binary (or the shadowlab process a CLI test runs) with a non-zero status.
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$here/lsan.supp:print_suppressions=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=0}
start=$(date +%s)
"$build/tests/shadowlab_tests" --gtest_filter="$filter" --gtest_brief=1
rc=$?
echo "shadowlab sanitized tests: exit $rc after $(($(date +%s) - start)) s (scenes + cli modules, ASan + UBSan)"
exit $rc
