#!/usr/bin/env bash
# `rollcheck fem-sds --vtu PATH` (docs/guide/fields.md): the body's triangles
# with the loop's per-face sums as named cell data. meshio (Debian's
# /usr/bin/python3) reads it; the score template (oracle/distribution_score.h)
# over the cell data gives the JSON's analytic SDS and the line-Hertz, FEM
# and FEM-FDS scores of the rulings, and the triangles' areas are
# face_areas_m2. The FEM's own sums are checked face by face against an
# independent computation: the cylinder's line load is uniform (F / L through
# its middle) on one radius, so every mapped point of every sample has the
# same line-Hertz peak p_L and the same FEM pressure p_F (the JSON's
# line_hertz_peak_pa and fem_peak_pa); a face's FEM sum is then its line-Hertz
# sum times p_F / p_L, and its Miner damage its count of samples (line-Hertz
# sum / p_L) times Basquin's (p_F / 2 / sigma_f')^(-1/b) with the preprint's
# sigma_f' = 700 MPa, b = -0.085 and endurance limit 250 MPa, which the load
# (3e7 N on the 1 m cylinder, p_F about 0.74 GPa) exceeds. The caps hold
# nothing. The path is checked before computing.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1

expect 0 "" -- "$bin" -q fem-sds --body cylinder --samples-per-loop 512 --orientations 1 --fem-slices 2 --slab-check 0 \
  --load 3e7 --vtu "$tmp/cylinder.vtu" --json "$tmp/cylinder.json"
/usr/bin/python3 - "$tmp/cylinder.vtu" "$tmp/cylinder.json" << 'PY' || fail=1
import json, sys
import meshio
import numpy as np
mesh = meshio.read(sys.argv[1])
result = json.load(open(sys.argv[2]))
triangles = mesh.cells_dict["triangle"]
cells = {name: values[0] for name, values in mesh.cell_data.items()}
ok = True
def need(condition, what):
    global ok
    if not condition:
        print("FAIL:", what); ok = False
names = ("face_areas_m2", "accumulated_point_hertz_pressure_pa", "accumulated_line_hertz_pressure_pa",
         "accumulated_fem_pressure_pa", "accumulated_fem_fatigue_damage")
need(sorted(cells) == sorted(names), f"cell data {sorted(cells)}")
need(len(triangles) == result["n_faces"], f"{len(triangles)} triangles for n_faces {result['n_faces']}")
p = mesh.points[triangles]
areas = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
need(np.allclose(areas, cells["face_areas_m2"], rtol=1e-9), "triangle areas are not face_areas_m2")
def score(x, a):  # the preprint's template: (1/A) sum a_i (x_i / sum x - a_i / A)^2
    return np.sum(a * (x / x.sum() - a / a.sum()) ** 2) / a.sum()
a = cells["face_areas_m2"]
loop = result["loop"]
for name, key in (("accumulated_point_hertz_pressure_pa", result["analytic_sds"]),
                  ("accumulated_line_hertz_pressure_pa", loop["line_hertz_sds_rulings"]["value"]),
                  ("accumulated_fem_pressure_pa", loop["fem_sds_rulings"]["value"]),
                  ("accumulated_fem_fatigue_damage", loop["fem_fds_rulings"]["value"])):
    need(cells[name].max() > 0, f"{name}: no face was loaded")
    need(abs(score(cells[name], a) / key - 1) < 1e-9, f"{name}: score {score(cells[name], a)} against the JSON's {key}")
need(loop["singular_samples"] == 0, "the cylinder rolls on rulings only")
line, fem, damage = (cells[n] for n in ("accumulated_line_hertz_pressure_pa", "accumulated_fem_pressure_pa",
                                         "accumulated_fem_fatigue_damage"))
p_line, p_fem = loop["line_hertz_peak_pa"], loop["fem_peak_pa"]
need(p_fem / 2 > 250e6, f"FEM peak {p_fem} Pa: the amplitude is below the endurance limit")
need(np.allclose(fem, line * p_fem / p_line, rtol=1e-9, atol=0), "FEM sums are not line-Hertz sums times p_F / p_L")
counts = line / p_line
need(np.allclose(counts, np.round(counts), rtol=0, atol=1e-9), "line-Hertz sums are not whole samples of p_L")
need(np.allclose(damage, counts * (p_fem / 2 / 700e6) ** (1 / 0.085), rtol=1e-9, atol=0),
     "FEM damage is not the samples' Basquin damage at p_F / 2")
z = p[:, :, 2]  # the cylinder's axis: a cap's triangle lies at one height
caps = z.max(axis=1) - z.min(axis=1) < 1e-9
need(caps.sum() > 0 and not fem[caps].any() and not damage[caps].any(), "the caps hold FEM pressure or damage")
sys.exit(0 if ok else 1)
PY
# Refused before any computation: a folder as the file, a missing folder.
refuses fem-sds "--body cylinder --vtu $tmp:--vtu" "--body cylinder --vtu $tmp/no/x.vtu:--vtu"
exit $fail
