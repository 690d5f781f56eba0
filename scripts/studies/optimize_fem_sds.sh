#!/usr/bin/env bash
# The FEM-SDS optimum of docs/results/optimize.md and its stability in the
# mesh: `rollcheck optimize --score fem-sds` (the continuum value) from the
# true oloid at 300 and 600 points per circle on two ranks, then the page's
# section between its markers (scripts/studies/optimize_fem_sds_page.py).
# Usage: scripts/studies/optimize_fem_sds.sh [ROLLCHECK_BINARY] [OUT_DIR] [MAX_EVALUATIONS]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/optimize_fem_sds}
evaluations=${3:-30}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for points in 300 600; do
  start=$(date +%s)
  mpirun -n 2 --oversubscribe "$bin" optimize --score fem-sds --oracle rolling --family centre-line \
    --points "$points" --max-evaluations "$evaluations" --json "$out/optimize_$points.json" \
    > "$out/optimize_$points.log" 2>&1 \
    || { echo "optimize at $points points failed: see $out/optimize_$points.log" >&2; exit 1; }
  echo "$points points per circle: $(( $(date +%s) - start )) s" >&2
done
/usr/bin/python3 "$here/scripts/studies/optimize_fem_sds_page.py" "$out/optimize_300.json" "$out/optimize_600.json" \
  "$("$bin" --version | head -1)" "$here/docs/results/optimize.md"
