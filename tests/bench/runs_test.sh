#!/usr/bin/env bash
# bench_common.cpp's --runs, end to end: a benchmark run N times over lists every run of every case in one
# Markdown table (each run's ratio, the median of the ratios, each renderer's range) under the CPU and the SIMD
# path; --json-dir keeps each run's JSON and the collected rows; runs that fail are named and make the exit code 1;
# with --scaling every count runs in every run; a bad --runs value is one line on stderr and exit code 2. The
# ratios need llvmpipe: without it the rest is checked and the test reports itself skipped (exit 77).
#   runs_test.sh BENCH_DEPTH BENCH_PCF
set -uo pipefail
depth=$1 pcf=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
export SHADOWLAB_ASSETS=/nonexistent  # the generated soups only (see isa_dispatch_test.sh)
strip() { sed 's/\x1b\[[0-9;]*m//g'; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# Shadowlab alone: every run listed, no ratio to show.
out=$("$depth" --smoke --no-llvmpipe --threads 2 --runs 2 --json-dir "$tmp" 2>&1 | strip) || fail "depth --runs 2: $out"
grep -q "^2 run(s) of shadowlab_bench_depth, .*logical CPUs, SIMD path [a-z0-9]* .*llvmpipe did not run" <<<"$out" ||
  fail "no heading naming the runs, the CPU, the SIMD path and the missing ratios: $out"
for r in 1 2; do
  [ "$(grep -c "^==== shadowlab_bench_depth, 2 thread(s), run $r of 2\$" <<<"$out")" = 1 ] || fail "run $r not once"
  [ -s "$tmp/shadowlab_bench_depth_t2_run$r.json" ] || fail "no JSON of run $r"
done
for c in a_small_10px b_large_2000px; do
  row=$(grep "^| $c | 2 | " <<<"$out") || fail "no row for $c: $out"
  # runs, median, shadowlab ms (a number or a range), llvmpipe ms, front / back
  grep -Eq "^\| $c \| 2 \| — / — \| — \| [0-9]+\.[0-9]{2}(–[0-9]+\.[0-9]{2})? \| — \| [0-9.–]+ / [0-9.–]+ \|$" <<<"$row" ||
    fail "unexpected row without llvmpipe: $row"
  for r in 1 2; do
    grep -q "{\"case\": \"$c\", \"threads\": 2, \"run\": $r, \"shadowlab_ms\": [0-9.]*[1-9]" \
      "$tmp/shadowlab_bench_depth_runs.json" || fail "collected JSON lacks $c run $r"
  done
  grep -q "{\"case\": \"$c\", \"threads\": 2, \"runs\": 2, \"ratios\": \[\]" "$tmp/shadowlab_bench_depth_runs.json" ||
    fail "collected JSON has no summary of $c"
done
grep -q '"failed": \[\]' "$tmp/shadowlab_bench_depth_runs.json" || fail "collected JSON names failed runs"

# --json-dir names a directory not made yet: it is made (and its parents), in either form; a file in the way or
# no value is one line and exit code 2, before any run.
out=$("$depth" --smoke --no-llvmpipe --threads 1 --runs 1 --benchmark_filter=b_large --json-dir="$tmp/new/sub" 2>&1 | strip) ||
  fail "--json-dir=DIR not made yet: $out"
[ -s "$tmp/new/sub/shadowlab_bench_depth_t1_run1.json" ] && [ -s "$tmp/new/sub/shadowlab_bench_depth_runs.json" ] ||
  fail "--json-dir=DIR not made yet: no JSON in it: $(ls -R "$tmp/new" 2>&1)"
: >"$tmp/plainfile"
for args in "--json-dir $tmp/plainfile/x" "--json-dir" "--json-dir="; do
  err=$("$depth" --smoke --no-llvmpipe --runs 1 $args 2>&1 >"$tmp/stdout")
  rc=$?
  [ $rc -eq 2 ] || fail "$args: exit $rc, not 2"
  [ "$(wc -l <<<"$err")" = 1 ] && grep -q "^--json-dir: " <<<"$err" || fail "$args: $err"
  [ ! -s "$tmp/stdout" ] || fail "$args started runs: $(cat "$tmp/stdout")"
done

# One run, written --runs=1: still the table.
out=$("$depth" --smoke --no-llvmpipe --threads 1 --runs=1 2>&1 | strip) || fail "depth --runs=1: $out"
grep -q "^| b_large_2000px | 1 | — | — | [0-9.]* | — | " <<<"$out" || fail "--runs=1 gives no table: $out"

# Runs that fail (here each run's own JSON cannot be written; no --json-dir, so the collected file is not what
# fails) are named, and the exit code says so.
out=$("$depth" --smoke --no-llvmpipe --threads 2 --runs 2 --benchmark_out="$tmp/missing/dir/out.json" 2>&1 | strip)
rc=$?
[ $rc -eq 1 ] || fail "failing runs: exit $rc, not 1"
for r in 1 2; do
  grep -q "^Failed: run $r, 2 thread(s): exit [1-9][0-9]* (its rows are missing above)\$" <<<"$out" ||
    fail "failed run $r not named: $out"
done

# With --scaling: each run takes every count.
out=$("$pcf" --smoke --no-llvmpipe --scaling 1,2 --runs 2 --benchmark_filter=no_lookup 2>&1 | strip) ||
  fail "pcf --scaling 1,2 --runs 2: $out"
for r in 1 2; do
  for t in 1 2; do
    [ "$(grep -c "^==== shadowlab_bench_pcf, $t thread(s), run $r of 2\$" <<<"$out")" = 1 ] || fail "no run $r at $t"
  done
done
grep -q "^Scaling, shadowlab_bench_pcf (.*the median over the runs" <<<"$out" || fail "no scaling table over the runs"
for t in 1 2; do grep -q "^| no_lookup | $t | — / — | " <<<"$out" || fail "no runs row at $t threads: $out"; done

# Bad values.
for v in 0 -3 abc 1001 ""; do
  for form in space equals; do
    if [ $form = space ]; then err=$("$depth" --runs "$v" 2>&1 >"$tmp/stdout"); else err=$("$depth" "--runs=$v" 2>&1 >"$tmp/stdout"); fi
    rc=$?
    [ $rc -eq 2 ] || fail "--runs '$v' ($form): exit $rc, not 2"
    [ "$(wc -l <<<"$err")" = 1 ] && grep -q "^--runs: expected a whole number of runs from 1 to 1000, got '$v'\$" <<<"$err" ||
      fail "--runs '$v' ($form): $err"
    [ ! -s "$tmp/stdout" ] || fail "--runs '$v' ($form) printed: $(cat "$tmp/stdout")"
  done
done

# Beside llvmpipe: four ratios per case, their median the mean of the middle two (as printed, to rounding).
out=$("$pcf" --smoke --threads 1 --runs 4 2>&1 | strip) || fail "pcf --runs 4: $out"
if grep -q "llvmpipe unavailable" <<<"$out"; then
  echo "llvmpipe unavailable: everything but the ratios checked"
  exit 77
fi
for c in no_lookup pcf_1_tap poisson_16_taps; do
  row=$(grep "^| $c | 1 | " <<<"$out") || fail "no row for $c: $out"
  awk -F'|' '{
    gsub(/[ ×*]/, "", $4); gsub(/[ ×*]/, "", $5)
    n = split($4, r, "/"); if (n != 4) exit 1
    for (i = 1; i <= 4; ++i) for (j = i + 1; j <= 4; ++j) if (r[j] + 0 < r[i] + 0) { t = r[i]; r[i] = r[j]; r[j] = t }
    m = (r[2] + r[3]) / 2; d = m - $5; if (d < 0) d = -d
    if (d > 0.011 || r[1] + 0 <= 0) exit 1
    split($6, s, "–"); split($7, l, "–"); if (s[1] + 0 <= 0 || l[1] + 0 <= 0) exit 1
  }' <<<"$row" || fail "row $row: not four ratios with their median and both renderers' times"
done
echo "ok"
