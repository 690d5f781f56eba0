#!/usr/bin/env bash
# Regenerates docs/results/flat-rim.md: the finished oloid's vertex
# (`rollcheck flat-rim`, rigid plane and steel block) and its flattest ends
# on the rigid plane (`rollcheck flat-rim --end-angle A`, the flat-rim
# table's nodes at 160 and 170 deg), one process each, every JSON
# under OUT_DIR (default results/flat-rim); then
# scripts/studies/flat_rim_page.py writes the page from those files alone.
# Usage: scripts/studies/flat_rim.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/flat-rim}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
"$bin" -q flat-rim --json "$out/vertex_rigid.json" > /dev/null
"$bin" -q flat-rim --counter-face steel --json "$out/vertex_steel.json" > /dev/null
for angle in 160 170; do
  "$bin" -q flat-rim --end-angle "$angle" --json "$out/end_${angle}_rigid.json" > /dev/null
done
/usr/bin/python3 "$here/scripts/studies/flat_rim_page.py" "$out" "$("$bin" --version | head -1)" \
  > "$here/docs/results/flat-rim.md"
