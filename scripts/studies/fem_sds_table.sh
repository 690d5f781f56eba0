#!/bin/bash
# The FEM-SDS tables of docs/results/fem-sds.md: runs the four fem-sds cases on two
# ranks and prints, over one loop of real rolling each, the preprint's
# point-Hertz SDS, the line-Hertz SDS and FEM-SDS with their convergence (FEM
# table K to 2K, samples halved), the oloid/cylinder discrimination under
# each, the 12 directly solved orientations (table against direct FEM,
# creases), and the 3D slab check of each body's first orientation (peak
# against the slices, end-section pressure over the nearest slice's, at two
# section levels; about 35 minutes, skipped with SLAB=0). Results (JSON,
# table.md, plots) go to OUT/<case>/.
#   [SLAB=0] bash scripts/studies/fem_sds_table.sh [BINARY] [OUT]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
binary=${1:-$here/build/src/cli/rollcheck}
out=${2:-results/fem_sds}
slab=${SLAB:-1}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for name in oloid paper_oloid cylinder candidate; do
  mpirun -n 2 "$binary" run "$here/cases/fem_sds_$name.toml" --set "out=$out/$name" --set "slab_orientations=$slab" \
    --json "$out/$name.json" > "$out/$name.log" 2>&1 || { echo "case $name failed: see $out/$name.log" >&2; exit 1; }
done
/usr/bin/python3 - "$out" <<'PY'
import json, sys
out = sys.argv[1]
runs = {n: json.load(open(f"{out}/{n}.json")) for n in ("oloid", "paper_oloid", "cylinder", "candidate")}
print("| body | faces | samples | point-Hertz SDS (the preprint's) | line-Hertz SDS | FEM-SDS | FEM-SDS K to 2K | "
      "FEM-SDS half samples | FEM solves | FEM-SDS / line-Hertz | table vs direct FEM | worst FEM refinement change | s |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for name, r in runs.items():
    print(f"| {r['body']} | {r['n_faces']} | {r['samples']} | {r['analytic_sds']:.4g} | {r['line_hertz_sds']:.4g} | "
          f"{r['fem_sds']:.4g} | {100 * r['fem_sds_table_change']:+.3f} % | {100 * r['fem_sds_sample_change']:+.3f} % | "
          f"{r['fem_solves']} | {r['fem_sds_over_line_hertz_sds']:.4f} | {100 * r['table_vs_direct_worst']:.2f} % | "
          f"{100 * r['fem_peak_worst_refinement_change']:.2f} % | {r['wall_s']:.0f} |")
cyl = runs["cylinder"]
print()
print("| SDS body / cylinder over the loop | point Hertz (the preprint's formula) | line Hertz | FEM |")
print("|---|---|---|---|")
for name in ("oloid", "paper_oloid", "candidate"):
    r = runs[name]
    print(f"| {r['body']} / cylinder | {r['analytic_sds'] / cyl['analytic_sds']:.4g} | "
          f"{r['line_hertz_sds'] / cyl['line_hertz_sds']:.4g} | {r['fem_sds'] / cyl['fem_sds']:.4g} |")
print()
print("| body | orientations solved directly | reach a crease | reach an obtuse rim | FEM vs line Hertz worst | "
      "slowest orientation (s) |")
print("|---|---|---|---|---|---|")
for name, r in runs.items():
    print(f"| {r['body']} | {r['fem_solved_orientations']} of {r['orientations']} | {r['orientations_reaching_crease']} | "
          f"{r['orientations_reaching_obtuse_rim']} | {100 * r['fem_vs_line_hertz_worst']:.2f} % | "
          f"{r['max_orientation_wall_s']:.1f} |")
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
