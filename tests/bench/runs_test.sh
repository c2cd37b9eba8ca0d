#!/usr/bin/env bash
# bench_common.cpp's --runs, end to end: a benchmark run N times over lists every run of every case in one
# Markdown table (each run's ratio, the median of the ratios, each renderer's range), under the CPU and the SIMD
# path; --json-dir keeps each run's JSON and the collected rows; with --scaling every count appears in every run;
# a bad --runs value is one line on stderr and exit code 2.
#   runs_test.sh BENCH_DEPTH BENCH_PCF
set -uo pipefail
depth=$1 pcf=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
export SHADOWLAB_ASSETS=/nonexistent  # the generated soups only (see isa_dispatch_test.sh)
strip() { sed 's/\x1b\[[0-9;]*m//g'; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Shadowlab alone: every run listed, no ratio to show.
out=$("$depth" --smoke --no-llvmpipe --threads 2 --runs 2 --json-dir "$tmp" 2>&1 | strip) || fail "depth --runs 2 failed: $out"
grep -q "^2 runs of shadowlab_bench_depth, .*logical CPUs, SIMD path [a-z0-9]* " <<<"$out" ||
  fail "no heading naming the runs, the CPU and the SIMD path: $out"
[ "$(grep -c '^==== shadowlab_bench_depth, 2 thread(s), run [12] of 2$' <<<"$out")" = 2 ] || fail "not two runs at 2 threads"
for c in a_small_10px b_large_2000px; do
  row=$(grep "^| $c | 2 | " <<<"$out") || fail "no row for $c: $out"
  # runs, median, shadowlab ms (a number or a range), llvmpipe ms, front / back
  grep -Eq "^\| $c \| 2 \| — / — \| — \| [0-9]+\.[0-9]{2}(–[0-9]+\.[0-9]{2})? \| — \| [0-9.–]+ / [0-9.–]+ \|$" <<<"$row" ||
    fail "unexpected row without llvmpipe: $row"
done
for r in 1 2; do [ -s "$tmp/shadowlab_bench_depth_t2_run$r.json" ] || fail "no JSON of run $r"; done
python3 - "$tmp/shadowlab_bench_depth_runs.json" <<'PY' || fail "collected JSON is wrong"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["runs"] == 2 and d["simd_path"] and "logical CPUs" in d["cpu"], d
runs = sorted((r["case"], r["run"]) for r in d["each_run"])
assert runs == [("a_small_10px", 1), ("a_small_10px", 2), ("b_large_2000px", 1), ("b_large_2000px", 2)], runs
assert all(r["shadowlab_ms"] > 0 and r["threads"] == 2 for r in d["each_run"]), d["each_run"]
PY

# Beside llvmpipe where it is there: three ratios per case and their median.
out=$("$pcf" --smoke --threads 1 --runs 3 2>&1 | strip) || fail "pcf --runs 3 failed: $out"
if grep -q "llvmpipe unavailable" <<<"$out"; then
  echo "llvmpipe unavailable: the ratio columns are not checked"
else
  for c in no_lookup pcf_1_tap poisson_16_taps; do
    row=$(grep "^| $c | 1 | " <<<"$out") || fail "no row for $c: $out"
    python3 - "$row" <<'PY' || fail "row $row: the median is not the middle run's ratio"
import re, sys
cells = [c.strip() for c in sys.argv[1].strip().strip("|").split("|")]
ratios = sorted(float(x) for x in cells[2].rstrip("×").split(" / "))
assert len(ratios) == 3, cells
median = float(re.fullmatch(r"\*\*([0-9.]+)×\*\*", cells[3]).group(1))
assert abs(median - ratios[1]) < 0.006, (median, ratios)
for ms in (cells[4], cells[5]):
    lo, _, hi = ms.partition("–")
    assert float(lo) > 0 and (not hi or float(hi) >= float(lo)), ms
PY
  done
fi

# With --scaling: each run takes every count.
out=$("$pcf" --smoke --no-llvmpipe --scaling 1,2 --runs 2 --benchmark_filter=no_lookup 2>&1 | strip) ||
  fail "pcf --scaling 1,2 --runs 2 failed: $out"
[ "$(grep -c '^==== shadowlab_bench_pcf, [12] thread(s), run [12] of 2$' <<<"$out")" = 4 ] || fail "not four processes: $out"
grep -q "^Scaling, shadowlab_bench_pcf (.*medians over the runs)" <<<"$out" || fail "no scaling table over the runs"
for t in 1 2; do grep -q "^| no_lookup | $t | — / — | " <<<"$out" || fail "no runs row at $t threads: $out"; done

# Bad values.
for v in 0 -3 abc 1001 ""; do
  err=$("$depth" --runs "$v" 2>&1 >"$tmp/stdout")
  rc=$?
  [ $rc -eq 2 ] || fail "--runs '$v': exit $rc, not 2"
  [ "$(wc -l <<<"$err")" = 1 ] && grep -q "^--runs: expected a whole number of runs from 1 to 1000, got '$v'\$" <<<"$err" ||
    fail "--runs '$v': $err"
  [ ! -s "$tmp/stdout" ] || fail "--runs '$v' printed: $(cat "$tmp/stdout")"
done
echo "ok"
