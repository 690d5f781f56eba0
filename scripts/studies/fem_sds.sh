#!/usr/bin/env bash
# Regenerates docs/results/fem-sds.md: the four bodies over one loop
# (scripts/studies/fem_sds_table.sh with SLAB=0), the cost
# (scripts/bench/bench_fem_sds.sh, its JSON kept) and the crease (`rollcheck
# crease --levels 5`), their JSON under OUT_DIR (default results/fem-sds); then
# scripts/studies/fem_sds_page.py writes the page from those files alone, and
# scripts/studies/fem_sds_family.sh writes the family's section. The 3D slab
# (over half an hour on 2 ranks) is not rerun: its table is in
# docs/notes/fem-sds-slab-table.md.
# Usage: scripts/studies/fem_sds.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/fem-sds}
mkdir -p "$out"
SLAB=0 bash "$here/scripts/studies/fem_sds_table.sh" "$bin" "$out/bodies" > "$out/bodies.md"
bash "$here/scripts/studies/fem_sds_family.sh" "$bin" "$out/family"
bash "$here/scripts/bench/bench_fem_sds.sh" "$bin" "$out/cost" > "$out/cost.txt"
/usr/bin/time -f '{"wall_s": %e, "user_s": %U, "system_s": %S}' -o "$out/crease.time.json" \
  "$bin" -q crease --levels 5 --json "$out/crease.json" > "$out/crease.log" 2>&1 \
  || { echo "crease failed: see $out/crease.log" >&2; exit 1; }
/usr/bin/python3 "$here/scripts/studies/fem_sds_page.py" "$out" "$("$bin" --version | head -1)" \
  "$here/docs/results/fem-sds.md"
