#!/usr/bin/env bash
# The FEM-SDS family of docs/results/fem-sds.md, ranked by the continuum value,
# and its stability: `rollcheck search --grid quick --score fem-sds` on two
# ranks at 300 and 600 points per circle; exits 1 unless every scored
# genome's fem_sds_continuum changes by under 1 % between them and is
# converged by its own status (half its loop quadrature, every other node of
# the FEM table), and the five best bodies are the same at both; then writes the page's family section (between
# its markers) with scripts/studies/fem_sds_family_page.py.
# Usage: scripts/studies/fem_sds_family.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/fem_sds_family}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for points in 300 600; do
  start=$(date +%s)
  mpirun -n 2 --oversubscribe "$bin" search --grid quick --score fem-sds --points "$points" \
    --json "$out/family_$points.json" > "$out/family_$points.log" 2>&1 \
    || { echo "family at $points points failed: see $out/family_$points.log" >&2; exit 1; }
  echo "$points points per circle: $(( $(date +%s) - start )) s" >&2
done
/usr/bin/python3 "$here/scripts/studies/fem_sds_family_page.py" "$out/family_300.json" "$out/family_600.json" \
  "$("$bin" --version | head -1)" "$here/docs/results/fem-sds.md"
