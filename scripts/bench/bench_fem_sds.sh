#!/usr/bin/env bash
# Benchmark (not a test) of FEM-SDS on 2 ranks:
#  1. the oloid's default run (whole loop, converged, 2 orientations solved
#     directly): its wall time, the FEM cost of one orientation solved directly
#     (9 slices at two mesh levels, the method before the scaled table), the
#     table's FEM cost per orientation for 12 orientations (the old sample) and
#     for every sample of the loop, their ratios, and the table's agreement
#     with the direct solves (the same accuracy?);
#  2. the whole quick-grid family table (`search --grid quick --score fem-sds`).
# With JSON_DIR, the runs' JSON (oloid.json, family.json) and their wall and CPU
# seconds (oloid.time.json, family.time.json: wall_s, user_s, system_s of
# mpirun and its ranks) are kept there (scripts/studies/fem_sds.sh reads them).
#   bash scripts/bench/bench_fem_sds.sh [ROLLCHECK] [JSON_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
json=${2:-$tmp}
mkdir -p "$json"
timed() { # NAME COMMAND...: the command's wall and CPU seconds in $json/NAME.time.json
  local name=$1; shift
  /usr/bin/time -f '{"wall_s": %e, "user_s": %U, "system_s": %S}' -o "$json/$name.time.json" "$@" \
    > /dev/null 2> "$tmp/log" || { cat "$tmp/log"; exit 1; }
}
timed oloid mpirun -n 2 "$bin" fem-sds --body oloid --json "$json/oloid.json"
timed family mpirun -n 2 "$bin" search --grid quick --score fem-sds --json "$json/family.json"
/usr/bin/python3 - "$json" <<'PY'
import json, sys
tmp = sys.argv[1]
oloid_s, family_s = (json.load(open(f"{tmp}/{name}.time.json"))["wall_s"] for name in ("oloid", "family"))
r = json.load(open(f"{tmp}/oloid.json"))
direct = [o["wall_s"] for o in r["per_orientation"] if o["fem_solved"]]
per_direct = sum(direct) / len(direct)
table = r["fem_table_wall_s"]
print(f"oloid, default run: {oloid_s:.1f} s wall on 2 ranks (limit 60 s); FEM-SDS {r['fem_sds']:.4g} "
      f"({r['fem_sds_status']}, K-to-2K {100 * r['fem_sds_table_change']:+.3f} %, half samples "
      f"{100 * r['fem_sds_sample_change']:+.3f} %)")
print(f"  one orientation solved directly (9 slices x 2 levels): {per_direct:.2f} s")
print(f"  the table: {r['fem_solves']} solves, {table:.2f} s for {r['samples']} samples")
print(f"  FEM per orientation, 12 orientations from the table: {table / 12:.3f} s ({per_direct / (table / 12):.1f}x "
      f"below direct)")
print(f"  FEM per orientation, every sample of the loop: {1e3 * table / r['samples']:.3f} ms "
      f"({per_direct / (table / r['samples']):.0f}x below direct)")
print(f"  accuracy: table against direct FEM {100 * r['table_vs_direct_worst']:.3f} %, direct FEM one level finer "
      f"{100 * r['fem_peak_worst_refinement_change']:.3f} %, table nodes one level finer "
      f"{100 * r['loop']['fem_worst_refinement_change']:.3f} %")
f = json.load(open(f"{tmp}/family.json"))
rows = f["genomes"] + f["references"]
print(f"quick-grid family: {family_s:.1f} s wall on 2 ranks (limit 900 s); {len(rows)} bodies, "
      f"{sum(x['scored'] for x in rows)} scored over a whole loop; {f['fem_solves']} FEM solves shared, "
      f"{f['fem_table_wall_s']:.1f} s of FEM")
PY
