#!/usr/bin/env bash
# Runs shadowlab's libFuzzer targets (ASan + UBSan), building them first when needed.
#   tests/fuzz/run.sh ci          every target for SHADOWLAB_FUZZ_SECONDS (default 45) seconds: the CI job
#   tests/fuzz/run.sh MINUTES     a campaign: every target for MINUTES minutes, one after the other
#   tests/fuzz/run.sh MINUTES fuzz_gltf ...   only the targets named
# Build directory: SHADOWLAB_FUZZ_BUILD (default build-fuzz in the repository). Each target's corpus grows in
# BUILD/fuzz-corpus/<target> (seeded from tests/fuzz/corpus/<target> and, for scenes, docs/examples); crashes,
# leaks, timeouts and out-of-memory inputs land in BUILD/fuzz-artifacts/<target>/. One summary line per target;
# the exit status is 1 when any target found something (the artifact and its reproducer command are printed).
set -uo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
build=${SHADOWLAB_FUZZ_BUILD:-$root/build-fuzz}
mode=${1:-ci}
shift || true
targets=("$@")
((${#targets[@]})) || targets=(fuzz_scene_json fuzz_gltf fuzz_exr_map fuzz_image_input fuzz_light_matrix)
if [ "$mode" = ci ]; then
  seconds=${SHADOWLAB_FUZZ_SECONDS:-45}
elif [[ "$mode" =~ ^[0-9]+$ ]] && [ "$mode" -gt 0 ]; then
  seconds=$((mode * 60))
else
  echo "usage: tests/fuzz/run.sh ci | MINUTES [TARGET...]" >&2
  exit 2
fi

if [ ! -f "$build/build.ninja" ]; then
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DSHADOWLAB_FUZZ=ON -DSHADOWLAB_TESTS=OFF -DSHADOWLAB_BENCH=OFF -DSHADOWLAB_GL_REFERENCE=OFF >/dev/null || exit 2
fi
# The build's output goes to a log; on failure its errors are printed, so that a CI log shows why.
mkdir -p "$build/fuzz-logs"
cmake --build "$build" --parallel "$(nproc)" --target "${targets[@]}" >"$build/fuzz-logs/build.log" 2>&1 || {
  grep -a -E 'error|FAILED|undefined reference' "$build/fuzz-logs/build.log" | head -20 | sed 's/^/  /' >&2
  echo "shadowlab fuzz: building the targets failed (log: $build/fuzz-logs/build.log;" \
    "run: cmake --build $build --target ${targets[*]})" >&2
  exit 2
}

# Each input is written to a file (the readers take paths, as the commands do): on tmpfs when there is one,
# since a disk file's truncate-and-write cost more than most targets' reading of it.
if [ -z "${TMPDIR:-}" ] && [ -d /dev/shm ] && [ -w /dev/shm ]; then export TMPDIR=/dev/shm; fi
# Leaks inside third-party libraries that our code cannot free (each one explained in the file).
export LSAN_OPTIONS=${LSAN_OPTIONS:-suppressions=$here/lsan.supp:print_suppressions=0}
status=0
for t in "${targets[@]}"; do
  corpus=$build/fuzz-corpus/$t
  artifacts=$build/fuzz-artifacts/$t/
  log=$build/fuzz-logs/$t.log
  mkdir -p "$corpus" "$artifacts" "$(dirname "$log")"
  cp -n "$here/corpus/$t/"* "$corpus/" 2>/dev/null
  [ "$t" = fuzz_scene_json ] && cp -n "$root/docs/examples/"*.json "$corpus/"
  stamp=$build/fuzz-logs/$t.start
  touch "$stamp"
  # Findings are crash-, leak-, timeout- and oom- files; a slow-unit- file is a note (over 10 s on a busy
  # machine), listed in the summary but not a failure.
  before=$(find "$artifacts" -type f ! -name 'slow-unit-*' | wc -l)
  # Sanitizer reports to files of their own too: the PNG reader silences stderr while libpng runs
  # (scenes/io/quiet_stderr.h), and a report made in that window would otherwise be lost.
  rm -f "$build/fuzz-logs/$t.sanitizer".*
  export ASAN_OPTIONS="log_path=$build/fuzz-logs/$t.sanitizer" UBSAN_OPTIONS="log_path=$build/fuzz-logs/$t.sanitizer"
  # Limits: 10 s per input, 2 GiB resident, no single allocation over 1 GiB (a reader that allocates what a
  # header claims before checking it shows up here as a finding). Leak checking stays on (the default).
  "$build/tests/fuzz/$t" -dict="$here/dict/shadowlab.dict" -max_total_time="$seconds" -timeout=10 \
    -rss_limit_mb=2048 -malloc_limit_mb=1024 -print_final_stats=1 -artifact_prefix="$artifacts" \
    "$corpus" >"$log" 2>&1
  rc=$?
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  cov=$(grep -o 'cov: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  ft=$(grep -o 'ft: [0-9]*' "$log" | tail -1 | cut -d' ' -f2)
  files=$(find "$corpus" -type f | wc -l)
  found=$(($(find "$artifacts" -type f ! -name 'slow-unit-*' | wc -l) - before))
  slow=$(find "$artifacts" -type f -name 'slow-unit-*' -newer "$stamp" | wc -l)
  printf '%-18s %4ss  runs %9s  cov %6s  ft %7s  corpus %5s  exit %d  findings %d  slow units %d\n' \
    "$t" "$seconds" "${runs:-?}" "${cov:-?}" "${ft:-?}" "$files" "$rc" "$found" "$slow"
  if [ "$rc" -ne 0 ] || [ "$found" -ne 0 ]; then
    status=1
    cat "$log" "$build/fuzz-logs/$t.sanitizer".* 2>/dev/null |
      grep -a -m1 -E 'ERROR: (AddressSanitizer|LeakSanitizer|libFuzzer)|runtime error|==ERROR' | sed 's/^/  /'
    find "$artifacts" -type f ! -name 'slow-unit-*' -newer "$stamp" | head -3 | sed "s|^|  reproduce: $build/tests/fuzz/$t |"
    echo "  log: $log (and $build/fuzz-logs/$t.sanitizer.PID)"
  fi
done
exit $status
