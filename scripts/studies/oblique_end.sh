#!/usr/bin/env bash
# The rims' oblique end of docs/results/rim-ends.md: the oloid loop's most
# oblique rim end solved with its edge crossing the ruling at the real angle
# and by the perpendicular reduction at its dihedral angle
# (`rollcheck rim --body oloid --oblique-study`, two ranks), then the page's
# section between its markers (scripts/studies/oblique_end_page.py).
# Usage: scripts/studies/oblique_end.sh [ROLLCHECK_BINARY] [OUT_DIR] [LEVELS]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
out=${2:-$here/results/oblique_end}
mkdir -p "$out"
bin=${1:-$here/build/src/cli/rollcheck}
start=$(date +%s)
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1 \
  mpirun -n 2 --oversubscribe "$bin" rim --body oloid --oblique-study --levels "${3:-2}" \
  --json "$out/oblique.json" > "$out/oblique.log" 2>&1 \
  || { echo "the oblique end failed: see $out/oblique.log" >&2; exit 1; }
echo "oblique study: $(( $(date +%s) - start )) s" >&2
/usr/bin/python3 "$here/scripts/studies/oblique_end_page.py" "$out/oblique.json" \
  "$("$bin" --version | head -1)" "$here/docs/results/rim-ends.md"
