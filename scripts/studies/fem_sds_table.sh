#!/bin/bash
# The FEM-SDS tables of docs/results/fem-sds.md: runs the four fem-sds cases on two
# ranks and prints, over one loop of real rolling each, the preprint's
# point-Hertz SDS, the line-Hertz SDS and FEM-SDS with their convergence (FEM
# table K to 2K, samples halved), the oloid/cylinder discrimination under
# each, the 12 directly solved orientations (table against direct FEM,
# creases), and the 3D slab check of each body's first orientation (peak
# against the slices, end-section pressure over the nearest slice's, at two
# section levels; about 35 minutes, skipped with SLAB=0). Results (plots) go
# to OUT/<case>/, each case's JSON to OUT/<case>.json, its wall and CPU
# seconds (/usr/bin/time: mpirun and its ranks) to OUT/<case>.time.json; the
# tables are printed by scripts/studies/fem_sds_page.py --tables.
#   [SLAB=0] bash scripts/studies/fem_sds_table.sh [BINARY] [OUT]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
binary=${1:-$here/build/src/cli/rollcheck}
out=${2:-results/fem_sds}
slab=${SLAB:-1}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for name in oloid paper_oloid cylinder candidate; do
  /usr/bin/time -f '{"wall_s": %e, "user_s": %U, "system_s": %S}' -o "$out/$name.time.json" \
    mpirun -n 2 "$binary" run "$here/cases/fem_sds_$name.toml" --set "out=$out/$name" --set "slab_check=$slab" \
    --json "$out/$name.json" > "$out/$name.log" 2>&1 || { echo "case $name failed: see $out/$name.log" >&2; exit 1; }
done
/usr/bin/python3 "$here/scripts/studies/fem_sds_page.py" --tables "$out"
