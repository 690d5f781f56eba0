#!/usr/bin/env bash
# `rollcheck oracle --vtu PATH` (docs/guide/fields.md): the body's triangles
# with its per-face arrays as named cell data. meshio (Debian's
# /usr/bin/python3) reads it; the cell data are the JSON's per-face arrays
# (--per-face) value for value, and the triangles' areas are face_areas_m2.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"

expect 0 "" -- "$bin" oracle --body oloid --oracle approx --per-face --vtu "$tmp/oloid.vtu" --json "$tmp/oloid.json"
/usr/bin/python3 - "$tmp/oloid.vtu" "$tmp/oloid.json" << 'PY' || fail=1
import json, sys
import meshio
import numpy as np
mesh = meshio.read(sys.argv[1])
per_face = json.load(open(sys.argv[2]))["per_face"]
triangles = mesh.cells_dict["triangle"]
ok = True
def need(condition, what):
    global ok
    if not condition:
        print("FAIL:", what); ok = False
for name in ("contact_counts", "stress_pa", "fatigue_damage", "face_areas_m2"):
    need(name in mesh.cell_data, f"cell data '{name}' missing: {sorted(mesh.cell_data)}")
for name, values in mesh.cell_data.items():
    need(len(values[0]) == len(triangles), f"{name}: {len(values[0])} values for {len(triangles)} triangles")
    need(np.array_equal(values[0], np.asarray(per_face[name], dtype=float)), f"{name} differs from the JSON's")
p = mesh.points[triangles]
areas = 0.5 * np.linalg.norm(np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0]), axis=1)
need(np.allclose(areas, mesh.cell_data["face_areas_m2"][0], rtol=1e-9), "triangle areas are not face_areas_m2")
need(mesh.cell_data["contact_counts"][0].max() > 0, "no face was touched")
sys.exit(0 if ok else 1)
PY
# Refused before any computation: real rolling has no per-face scores; a folder as the file.
refuses oracle "--oracle rolling --body oloid --vtu $tmp/r.vtu:--vtu" "--vtu $tmp:option --vtu"
check '[[ ! -e $tmp/r.vtu ]]' "a refused --vtu wrote a file"
# A write that fails (the file size limit, as a full disk would) is a failed
# computation: exit 1 naming the file, no file and no temporary left.
(trap '' XFSZ; ulimit -f 160; "$bin" -q oracle --body oloid --vtu "$tmp/small.vtu" > "$tmp/small.log" 2>&1)
rc=$?
check '[[ $rc -eq 1 ]] && grep -q "small.vtu" "$tmp/small.log"' "a failed VTU write gave exit $rc: $(head -c 300 "$tmp/small.log")"
check '[[ ! -e $tmp/small.vtu ]] && [[ -z $(ls -A "$tmp" | grep "tmp") ]]' "a failed VTU write left a file"
exit $fail
