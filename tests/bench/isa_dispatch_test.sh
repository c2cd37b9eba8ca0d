#!/usr/bin/env bash
# bench/isa_main.cpp, end to end: with no SHADOWLAB_ISA a benchmark runs the set the shadowlab executable reports
# (--version), SHADOWLAB_ISA forces each set the build has and the CPU can run, every such set's depth maps hash the
# same (shadowlab_bench_depth --smoke --verify) and the PCF bench runs on it, and an unknown set is refused with
# one line and exit code 2; on an emulated CPU without AVX the program takes the scalar path.
#   isa_dispatch_test.sh BENCH_DEPTH BENCH_PCF SHADOWLAB "avx2;avx512;scalar"
set -uo pipefail
depth=$1 pcf=$2 shadowlab=$3 isas=$4
fail() { echo "FAIL: $*" >&2; exit 1; }
# The generated soups only: the glTF dragon (../shared/assets) would make each run, and the emulated one most,
# slow, and the test would depend on the assets being there.
export SHADOWLAB_ASSETS=/nonexistent
strip() { sed 's/\x1b\[[0-9;]*m//g'; }

expected=$(env -u SHADOWLAB_ISA "$shadowlab" --version | sed -n 's/.*SIMD path \([a-z0-9]*\).*/\1/p')
[ -n "$expected" ] || fail "shadowlab --version names no SIMD path"
out=$(env -u SHADOWLAB_ISA "$depth" --smoke --threads 2 --no-llvmpipe 2>&1 | strip) || fail "default run failed"
grep -q "^simd_path: $expected\$" <<<"$out" || fail "default run does not report simd_path $expected: $(grep simd_path <<<"$out")"
grep -q "SIMD path $expected, medians" <<<"$out" || fail "default run's summary does not name $expected"

reference="" ran=0
for isa in ${isas//;/ }; do
  out=$(SHADOWLAB_ISA=$isa "$depth" --smoke --threads 2 --verify --no-llvmpipe 2>&1 | strip)
  rc=$?
  if [ $rc -ne 0 ] && grep -q "this CPU lacks" <<<"$out"; then
    echo "skip $isa: $(tail -1 <<<"$out")"
    continue
  fi
  [ $rc -eq 0 ] || fail "SHADOWLAB_ISA=$isa: exit $rc: $out"
  grep -q "^SIMD path $isa, 2 thread(s)\$" <<<"$out" || fail "SHADOWLAB_ISA=$isa did not run $isa: $out"
  hashes=$(grep -o "hash [0-9a-f]*" <<<"$out" | tr '\n' ' ')
  [ "$(wc -w <<<"$hashes")" -ge 4 ] || fail "SHADOWLAB_ISA=$isa: expected a map hash per case, got '$hashes'"
  if [ -z "$reference" ]; then reference=$hashes; ref_isa=$isa
  else [ "$hashes" = "$reference" ] || fail "$isa maps ($hashes) differ from $ref_isa's ($reference)"; fi
  pout=$(SHADOWLAB_ISA=$isa "$pcf" --smoke --threads 2 --no-llvmpipe 2>&1 | strip) || fail "PCF bench on $isa failed"
  grep -q "SIMD path $isa, medians" <<<"$pout" || fail "PCF bench with SHADOWLAB_ISA=$isa did not run $isa"
  echo "ok $isa: $hashes"
  ran=$((ran + 1))
done
[ $ran -ge 1 ] || fail "no set ran"

# On a CPU without AVX (QEMU's user-mode Nehalem, where Debian's qemu-user is installed) the program starts and
# takes the scalar path by itself.
if command -v qemu-x86_64 >/dev/null 2>&1 && [[ ";$isas;" == *";scalar;"* ]]; then
  out=$(env -u SHADOWLAB_ISA qemu-x86_64 -cpu Nehalem "$depth" --smoke --threads 2 --no-llvmpipe \
        --benchmark_filter=a_small 2>&1 | strip) || fail "no run on an emulated Nehalem: $out"
  grep -q "SIMD path scalar, medians" <<<"$out" || fail "an emulated Nehalem did not take the scalar path"
  echo "ok: an emulated Nehalem runs the scalar path"
else
  echo "skip the CPU without AVX: no qemu-x86_64, or no scalar set built"
fi

err=$(SHADOWLAB_ISA=sse9 "$depth" --smoke 2>&1 >/dev/null)
rc=$?
[ $rc -eq 2 ] || fail "SHADOWLAB_ISA=sse9: exit $rc, expected 2"
[ "$(wc -l <<<"$err")" -eq 1 ] || fail "SHADOWLAB_ISA=sse9: expected one error line, got: $err"
grep -q "error: SHADOWLAB_ISA: unknown instruction set" <<<"$err" || fail "SHADOWLAB_ISA=sse9: $err"
echo "ok: $ran set(s) agree; an unknown set is refused"
