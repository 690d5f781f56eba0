#!/usr/bin/env bash
# How long `rollcheck robustness` takes (the study's budget: 5 minutes on 2
# cores), over three runs, against `rollcheck oracle --oracle rolling --body
# oloid` (one rolling loop) as a ratio.
# Usage: scripts/bench/bench_robustness.sh [ROLLCHECK_BINARY]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
seconds_of() { local s; s=$(date +%s%N); "$@" > /dev/null 2>&1; echo $(( $(date +%s%N) - s )); }
one=$(seconds_of "$bin" oracle --oracle rolling --body oloid --json "$tmp/o.json")
for k in 1 2 3; do
  t=$(seconds_of "$bin" robustness --json "$tmp/r.json")
  awk -v k="$k" -v t="$t" -v one="$one" 'BEGIN { printf "robustness run %d: %.1f s, %.0f x one rolling loop (%.2f s), %.2f of the 300 s budget\n", k, t / 1e9, t / one, one / 1e9, t / 3e11 }'
done
