#!/usr/bin/env bash
# Benchmark (not a test) of the CI's two jobs on a built tree: the default
# test suite (`ctest -LE long -j JOBS`, what scripts/setup/run-tests.sh runs)
# and the main job (scripts/setup/run-main.sh). Prints the suite's sum of
# test times, its wall time, their ratio, its ten slowest tests, and the main
# job's wall time, against the budgets of issue 61 (sum about 450 s, suite
# wall 4 min, main job 90 s on 2 cores).
#   bash scripts/bench/bench_ci.sh [JOBS]        # JOBS defaults to 2
#   SKIP_MAIN=1 bash scripts/bench/bench_ci.sh   # the suite alone
#   SKIP_SUITE=1 bash scripts/bench/bench_ci.sh  # the main job alone
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
jobs=${1:-2}
build=$here/build
[[ -x $build/src/cli/rollcheck ]] || { echo "bench_ci: build first ($build/src/cli/rollcheck missing)" >&2; exit 2; }
source "$here/scripts/bench/bench_lib.sh"
now() { date +%s.%N; }

if [[ -z ${SKIP_SUITE:-} ]]; then
  start=$(now)
  # A failing test still has a time; the count of failures is printed below.
  ctest --test-dir "$build" -LE long -j "$jobs" > "$tmp/ctest.log" 2>&1 || true
  wall=$(echo "$(now) - $start" | bc -l)
  # Lines "  n/N Test  #k: NAME ......   Passed   12.34 sec".
  sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) .* ([0-9.]+) sec$/\2 \1/p' "$tmp/ctest.log" | sort -gr > "$tmp/times"
  count=$(wc -l < "$tmp/times")
  sum=$(awk '{s += $1} END {printf "%.1f", s}' "$tmp/times")
  failed=$(grep -cE '^ *[0-9]+/[0-9]+ Test .*(\*\*\*|Failed)' "$tmp/ctest.log" || true)
  printf 'default suite: %d tests (%d failed) at -j %d on %d cores\n' "$count" "$failed" "$jobs" "$(nproc)"
  printf 'sum of test times: %7.1f s (budget 450)\n' "$sum"
  printf 'wall time:         %7.1f s (budget 240)\n' "$wall"
  printf 'sum / wall:        %7.2f\n' "$(echo "$sum / $wall" | bc -l)"
  echo 'ten slowest (s):'
  head -10 "$tmp/times" | awk '{printf "  %7.1f  %s\n", $1, $2}'
fi

if [[ -z ${SKIP_MAIN:-} ]]; then
  start=$(now)
  bash "$here/scripts/setup/run-main.sh" > "$tmp/main.log" 2>&1 || { tail -20 "$tmp/main.log"; echo "main job failed" >&2; exit 1; }
  printf 'main job:          %7.1f s (budget 90)\n' "$(echo "$(now) - $start" | bc -l)"
fi
printf 'load average at the end: %s\n' "$(cut -d' ' -f1-3 /proc/loadavg)"
