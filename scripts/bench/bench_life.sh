#!/usr/bin/env bash
# How long `rollcheck life` takes (its budget: 10 minutes on 2 cores), against
# `rollcheck fem-sds --body oloid` (one loop of FEM slices) as a ratio.
# Usage: scripts/bench/bench_life.sh [ROLLCHECK_BINARY]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
source "$here/scripts/bench/bench_lib.sh"
run fem_sds "$bin" fem-sds --body oloid
run life "$bin" life
awk -v t="$(cat "$tmp/life.s")" -v one="$(cat "$tmp/fem_sds.s")" \
  'BEGIN { printf "life: %.1f s, %.2f x fem-sds --body oloid (%.1f s), %.2f of the 600 s budget\n", t, t / one, one, t / 600 }'
