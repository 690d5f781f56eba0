#!/usr/bin/env bash
# Benchmark (not a test) of FEM-SDS on 2 ranks:
#  1. the oloid's default run (whole loop, converged, 2 orientations solved
#     directly): its wall time, the FEM cost of one orientation solved directly
#     (9 slices at two mesh levels, the method before the scaled table), the
#     table's FEM cost per orientation for 12 orientations (the old sample) and
#     for every sample of the loop, their ratios, and the table's agreement
#     with the direct solves (the same accuracy?);
#  2. the whole quick-grid family table (`search --grid quick --score fem-sds`).
#   bash scripts/bench/bench_fem_sds.sh [ROLLCHECK]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
seconds() { # wall seconds of the command
  local start end
  start=$(date +%s.%N); "$@" > /dev/null 2> "$tmp/log" || { cat "$tmp/log"; exit 1; }; end=$(date +%s.%N)
  echo "$end - $start" | bc -l
}
oloid=$(seconds mpirun -n 2 "$bin" fem-sds --body oloid --json "$tmp/oloid.json")
family=$(seconds mpirun -n 2 "$bin" search --grid quick --score fem-sds --json "$tmp/family.json")
/usr/bin/python3 - "$tmp" "$oloid" "$family" <<'PY'
import json, sys
tmp, oloid_s, family_s = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
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
