#!/usr/bin/env bash
# Benchmark (not a test) of the CI's two jobs on a built tree: the default
# test suite (`ctest -LE long -j JOBS`, what scripts/setup/run-tests.sh runs)
# and the main job (scripts/setup/run-main.sh). Prints the suite's sum of
# test times, its wall time, their ratio, its CPU time (user + system of
# every test process: on a machine shared with other work the stable
# measure), its ten slowest tests, and the main job's wall and CPU time with
# the audit's costliest commands, against the budgets of issue 61 on 2 cores
# (a clean clone's set-up, build and suite under 600 s: the suite about
# 270 s wall, a sum near 500 s; the main job under 90 s).
#   bash scripts/bench/bench_ci.sh [JOBS]        # JOBS defaults to 2
#   SKIP_MAIN=1 bash scripts/bench/bench_ci.sh   # the suite alone
#   SKIP_SUITE=1 bash scripts/bench/bench_ci.sh  # the main job alone
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
jobs=${1:-2}
build=$here/build
[[ -x $build/src/cli/rollcheck ]] || { echo "bench_ci: build first ($build/src/cli/rollcheck missing)" >&2; exit 2; }
source "$here/scripts/bench/bench_lib.sh"
# Bash's `time` of a command: "WALL USER SYSTEM" seconds (its children's CPU included).
TIMEFORMAT='%3R %3U %3S'
load() { cut -d' ' -f1-3 /proc/loadavg; }

if [[ -z ${SKIP_SUITE:-} ]]; then
  printf 'load average before the suite: %s\n' "$(load)"
  # A failing test still has a time; the count of failures is printed below.
  { time ctest --test-dir "$build" -LE long -j "$jobs" > "$tmp/ctest.log" 2>&1 || true; } 2> "$tmp/suite.time"
  read -r wall user system < "$tmp/suite.time"; cpu=$(echo "$user + $system" | bc -l)
  # Lines "  n/N Test  #k: NAME ......   Passed   12.34 sec".
  sed -nE 's/^ *[0-9]+\/[0-9]+ Test +#[0-9]+: ([^ ]+) .* ([0-9.]+) sec$/\2 \1/p' "$tmp/ctest.log" | sort -gr > "$tmp/times"
  count=$(wc -l < "$tmp/times")
  sum=$(awk '{s += $1} END {printf "%.1f", s}' "$tmp/times")
  failed=$(grep -cE '^ *[0-9]+/[0-9]+ Test .*(\*\*\*|Failed)' "$tmp/ctest.log" || true)
  printf 'default suite: %d tests (%d failed) at -j %d on %d cores\n' "$count" "$failed" "$jobs" "$(nproc)"
  printf 'sum of test times: %7.1f s (budget 500)\n' "$sum"
  printf 'wall time:         %7.1f s (budget 270)\n' "$wall"
  printf 'CPU time:          %7.1f s (user + system of the test processes)\n' "$cpu"
  printf 'sum / wall:        %7.2f\n' "$(echo "$sum / $wall" | bc -l)"
  echo 'ten slowest (s):'
  head -10 "$tmp/times" | awk '{printf "  %7.1f  %s\n", $1, $2}'
  grep -E '^ *[0-9]+/[0-9]+ Test .*(\*\*\*|Failed)' "$tmp/ctest.log" || true
fi

if [[ -z ${SKIP_MAIN:-} ]]; then
  printf 'load average before the main job: %s\n' "$(load)"
  { time bash "$here/scripts/setup/run-main.sh" > "$tmp/main.log" 2>&1; } 2> "$tmp/main.time" \
    || { tail -20 "$tmp/main.log"; echo "main job failed" >&2; exit 1; }
  read -r wall user system < "$tmp/main.time"
  printf 'main job:          %7.1f s (budget 90)\n' "$wall"
  printf 'main job CPU time: %7.1f s\n' "$(echo "$user + $system" | bc -l)"
  # The audit's own account of its commands (audit/runner.cpp logs the costliest).
  grep -A10 "audit: the commands' CPU time" "$tmp/main.log" || true
fi
printf 'load average at the end: %s\n' "$(load)"
