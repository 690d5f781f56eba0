#!/usr/bin/env bash
# `rollcheck fem-sds --vtu PATH` (docs/guide/fields.md): the body's triangles
# with the loop's per-face sums as named cell data. meshio (Debian's
# /usr/bin/python3) reads it; the score template (oracle/distribution_score.h)
# over the cell data gives the JSON's analytic SDS and line-Hertz SDS of the
# rulings, and the triangles' areas are face_areas_m2. The path is checked
# before computing.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1

expect 0 "" -- "$bin" -q fem-sds --body cylinder --samples-per-loop 512 --orientations 1 --fem-slices 2 --slab-check 0 \
  --vtu "$tmp/cylinder.vtu" --json "$tmp/cylinder.json"
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
names = ("face_areas_m2", "accumulated_point_hertz_pressure_pa", "accumulated_line_hertz_pressure_pa")
need(sorted(cells) == sorted(names), f"cell data {sorted(cells)}")
need(len(triangles) == result["n_faces"], f"{len(triangles)} triangles for n_faces {result['n_faces']}")
p = mesh.points[triangles]
areas = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
need(np.allclose(areas, cells["face_areas_m2"], rtol=1e-9), "triangle areas are not face_areas_m2")
def score(x, a):  # the preprint's template: (1/A) sum a_i (x_i / sum x - a_i / A)^2
    return np.sum(a * (x / x.sum() - a / a.sum()) ** 2) / a.sum()
a = cells["face_areas_m2"]
for name, key in (("accumulated_point_hertz_pressure_pa", result["analytic_sds"]),
                  ("accumulated_line_hertz_pressure_pa", result["loop"]["line_hertz_sds_rulings"]["value"])):
    need(cells[name].max() > 0, f"{name}: no face was loaded")
    need(abs(score(cells[name], a) / key - 1) < 1e-9, f"{name}: score {score(cells[name], a)} against the JSON's {key}")
sys.exit(0 if ok else 1)
PY
# Refused before any computation: a folder as the file, a missing folder.
refuses fem-sds "--body cylinder --vtu $tmp:--vtu" "--body cylinder --vtu $tmp/no/x.vtu:--vtu"
exit $fail
