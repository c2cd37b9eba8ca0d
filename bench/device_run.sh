#!/bin/sh
# Runs the benchmarks of a bundle made by bench/device_bundle.sh (copied next to it as run.sh) on a bare x86-64
# Linux machine: unpacks into a fresh /tmp folder, makes the dynamic loader, libglvnd and Mesa use the bundle's
# libraries and llvmpipe only, checks bit-identical maps (--verify) at each thread count, then runs the depth and
# PCF benchmarks at each count with speed-up and efficiency tables. Everything goes to OUT_DIR:
#   sh run.sh [OUT_DIR]          (default: $OUT, else ./out next to this script)
# THREADS=1,2,4,8,16 (default) picks the counts, REPS=7 the repetitions per case (the two renderers' repetitions
# interleaved, as in README's table); SMOKE=1 runs a quick check
# only (small workloads, 1 and 2 threads, with the loader's trace in OUT_DIR/ld_debug.log).
# TESTS=FILTER first runs the bundle's test program (bin/shadowlab_tests, where the build had one) with that gtest
# filter ('*' for all), its output in OUT_DIR/tests.log.
# BEFORE=DIR compares instead: the depth-only benchmark of another build (DIR/shadowlab_bench_depth, DIR relative
# to the current folder or to this script's; same libraries) against the bundle's, ROUNDS=2 rounds at each count
# in THREADS (default 2,16), the two builds taking turns at going first.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-${OUT:-$here/out}}
mkdir -p "$out"
out=$(cd "$out" && pwd)
threads=${THREADS:-1,2,4,8,16}
reps=${REPS:-7}
interleave=--benchmark_enable_random_interleaving=true
before=
if [ -n "${BEFORE:-}" ]; then
  for d in "$BEFORE" "$here/$BEFORE"; do
    if [ -x "$d/shadowlab_bench_depth" ]; then before=$(cd "$d" && pwd); break; fi
  done
  [ -n "$before" ] || { echo "run.sh: no shadowlab_bench_depth in $BEFORE (nor in $here/$BEFORE)" >&2; exit 2; }
fi

tmp=$(mktemp -d /tmp/shadowlab-bundle.XXXXXX)
trap 'rm -rf "$tmp"' EXIT
if xz --version > /dev/null 2>&1; then
  xz -dc "$here/shadowlab-bundle.tar.xz" | tar -xf - -C "$tmp"
else
  LD_LIBRARY_PATH="$here/xz" "$here/xz/xz" -dc "$here/shadowlab-bundle.tar.xz" | tar -xf - -C "$tmp"
fi
b=$tmp/shadowlab-bundle
sed "s|@LIB@|$b/lib|" "$b/egl/50_mesa.json.in" > "$b/egl/50_mesa.json"

export LD_LIBRARY_PATH="$b/lib"
export __EGL_VENDOR_LIBRARY_FILENAMES="$b/egl/50_mesa.json"  # libglvnd: this vendor only
export __EGL_VENDOR_LIBRARY_DIRS="$b/egl"
export LIBGL_DRIVERS_PATH="$b/dri"                            # Mesa's loader: swrast_dri.so from the bundle
export EGL_PLATFORM=surfaceless
export LIBGL_ALWAYS_SOFTWARE=1
export GALLIUM_DRIVER=llvmpipe
export MESA_SHADER_CACHE_DISABLE=true
export SHADOWLAB_ASSETS="$b/assets"
export HOME="${HOME:-$tmp}"

{
  echo "== bundle"; cat "$b/BUILD_INFO"
  echo "== machine"; uname -a; ldd --version 2>&1 | head -1
  (command -v lscpu > /dev/null && lscpu) || grep -m1 'model name' /proc/cpuinfo
  echo "nproc $(nproc 2>/dev/null || getconf _NPROCESSORS_ONLN)"
} > "$out/machine.txt" 2>&1

status=0
if [ -n "${TESTS:-}" ]; then
  if [ -x "$b/bin/shadowlab_tests" ]; then
    echo "== tests ($TESTS)"
    "$b/bin/shadowlab_tests" --gtest_filter="$TESTS" > "$out/tests.log" 2>&1 || status=1
    grep -E '^\[ *(FAILED|PASSED|SKIPPED) *\]|tests? ran|Failure' "$out/tests.log" | head -40
  else
    echo "run.sh: TESTS is set but the bundle has no bin/shadowlab_tests" >&2
    status=1
  fi
fi
if [ -n "$before" ]; then
  for n in $(echo "${THREADS:-2,16}" | tr ',' ' '); do
    for r in $(seq "${ROUNDS:-2}"); do
      order="before after"
      [ $((r % 2)) = 0 ] && order="after before"
      for side in $order; do
        if [ $side = before ]; then prog=$before/shadowlab_bench_depth; else prog=$b/bin/shadowlab_bench_depth; fi
        "$prog" --threads "$n" --repetitions "$reps" "$interleave" > "$out/ab_${side}_t${n}_r$r.log" 2>&1 || status=1
        echo "== $side, $n thread(s), round $r"
        sed -n '/^Depth-only pass/,/^$/p' "$out/ab_${side}_t${n}_r$r.log" | tail -n +2
        grep '^[abc]_[^/ ]* .*, busy ' "$out/ab_${side}_t${n}_r$r.log" || true
      done
    done
  done
  exit $status
fi
if [ "${SMOKE:-0}" = 1 ]; then
  LD_DEBUG=libs "$b/bin/shadowlab_bench_depth" --smoke --verify --threads 2 > "$out/smoke_verify.log" 2> "$out/ld_debug.log" || status=1
  cat "$out/smoke_verify.log"
  # Every library opened from outside the bundle, glibc's excepted: there should be none.
  grep 'calling init:' "$out/ld_debug.log" | sed 's/.*calling init: //' | grep -v "^$b/" |
    grep -Ev '/(libc|libm|libdl|libpthread|librt|ld-linux-x86-64)\.so' > "$out/outside_libs.txt" || true
  if [ -s "$out/outside_libs.txt" ]; then echo "libraries from outside the bundle:"; cat "$out/outside_libs.txt"; status=1; fi
  "$b/bin/shadowlab_bench_depth" --smoke --scaling 1,2 --json-dir "$out" > "$out/smoke_depth.log" 2>&1 || status=1
  "$b/bin/shadowlab_bench_pcf" --smoke --scaling 1,2 --json-dir "$out" > "$out/smoke_pcf.log" 2>&1 || status=1
  sed -n '/^Scaling/,$p' "$out/smoke_depth.log" "$out/smoke_pcf.log"
  echo "smoke test: $([ $status = 0 ] && echo passed || echo FAILED), logs in $out"
  exit $status
fi

for n in $(echo "$threads" | tr ',' ' '); do
  echo "== --verify, $n thread(s)"
  "$b/bin/shadowlab_bench_depth" --verify --threads "$n" > "$out/verify_t$n.log" 2>&1 || status=1
  cat "$out/verify_t$n.log"
done
echo "== depth-only pass"
"$b/bin/shadowlab_bench_depth" --scaling "$threads" --repetitions "$reps" "$interleave" --json-dir "$out" > "$out/depth.log" 2>&1 || status=1
sed -n '/^Scaling/,$p' "$out/depth.log"
echo "== PCF pass"
"$b/bin/shadowlab_bench_pcf" --scaling "$threads" --repetitions "$reps" "$interleave" --json-dir "$out" > "$out/pcf.log" 2>&1 || status=1
sed -n '/^Scaling/,$p' "$out/pcf.log"
echo "done: $([ $status = 0 ] && echo all passed || echo 'something FAILED (see the logs)'), logs and JSON in $out"
exit $status
