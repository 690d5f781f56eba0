#!/bin/bash
# The README's FEM-SDS table: runs the four fem-sds cases on two ranks and
# prints analytic SDS, line-Hertz SDS, FEM-SDS, their ratios, the
# oloid/cylinder discrimination under each and the orientations that reach a
# crease, and the 3D slab check of each body's first orientation (peak
# against the slices, end-section pressure over the nearest slice's, at two
# section levels). Results (JSON, table.md, plots) go to OUT/<case>/.
#   bash scripts/fem_sds_table.sh [BINARY] [OUT]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
binary=${1:-$here/build/src/cli/rollcheck}
out=${2:-results/fem_sds}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for name in oloid paper_oloid cylinder candidate; do
  mpirun -n 2 "$binary" run "$here/cases/fem_sds_$name.toml" --set "out=$out/$name" \
    --json "$out/$name.json" > "$out/$name.log" 2>&1 || { echo "case $name failed: see $out/$name.log" >&2; exit 1; }
done
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
runs = {n: json.load(open(f"{out}/{n}.json")) for n in ("oloid", "paper_oloid", "cylinder", "candidate")}
print("| body | orientations (FEM solved) | reach a crease | reach an obtuse rim | analytic SDS | line-Hertz SDS | FEM-SDS | FEM-SDS / analytic | "
      "FEM-SDS / line-Hertz | worst FEM refinement change | slowest orientation (s) |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for name, r in runs.items():
    print(f"| {r['body']} | {r['orientations']} ({r['fem_solved_orientations']}) | {r['orientations_reaching_crease']} | "
          f"{r['orientations_reaching_obtuse_rim']} | "
          f"{r['analytic_sds']:.4g} | {r['line_hertz_sds']:.4g} | {r['fem_sds']:.4g} | {r['fem_sds'] / r['analytic_sds']:.4g} | "
          f"{r['fem_sds'] / r['line_hertz_sds']:.4f} | {100 * r['fem_peak_worst_refinement_change']:.2f} % | "
          f"{r['max_orientation_wall_s']:.1f} |")
cyl = runs["cylinder"]
print()
print("| oloid / cylinder SDS ratio | analytic (preprint) | line-Hertz | FEM |")
print("|---|---|---|---|")
for name in ("oloid", "paper_oloid", "candidate"):
    r = runs[name]
    print(f"| {r['body']} / cylinder | {r['analytic_sds'] / cyl['analytic_sds']:.4g} | "
          f"{r['line_hertz_sds'] / cyl['line_hertz_sds']:.4g} | {r['fem_sds'] / cyl['fem_sds']:.4g} |")
print()
print("| body | orientation (c) | slab level | DOFs | Newton | s | slab peak / slices' - 1 | "
      "max over slices abs(slab / slice - 1) | rim overhang (deg, s = 0, L) | end p / nearest slice p (s = 0, L) |")
print("|---|---|---|---|---|---|---|---|---|---|")
for name, r in runs.items():
    for o in r["per_orientation"]:
        for l in o.get("slab", []):
            first, last = o["slices"][0]["fem_peak_pa"], o["slices"][-1]["fem_peak_pa"]
            ends = [l["end_peak_pa"][0] / first if first > 0 else float("nan"),
                    l["end_peak_pa"][1] / last if last > 0 else float("nan")]
            print(f"| {r['body']} | {o['index']} ({o['centre_of_pressure']:.3f}) | {l['refine']} | {l['dofs']} | "
                  f"{l['newton_iterations']} | {l['wall_s']:.1f} | {100 * l['peak_difference_vs_slices']:+.2f} % | "
                  f"{100 * l['max_slice_difference']:.2f} % | {o['rim_overhang_deg'][0]:.1f}, {o['rim_overhang_deg'][1]:.1f} | "
                  f"{ends[0]:.3f}, {ends[1]:.3f} |")
PY
