#!/usr/bin/env bash
# The fields of a 3D Hertz solve on two ranks are one XDMF file that Debian's
# python3-meshio reads whole: one grid, every field on its nodes, float64; the
# file's contact pressure peak is the JSON's nodal peak. An output path whose
# folder is missing is refused before any computation.
#   fields_meshio.sh ROLLCHECK SOURCE_DIR TMP_DIR
set -u
bin=$1; tmp=$3
mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
fail=0
rm -f "$tmp/f.xdmf" "$tmp/f.json"
mpirun -n 2 "$bin" -q hertz --model 3d --refine 0 --xdmf "$tmp/f.xdmf" --json "$tmp/f.json" || { echo "FAIL: solve"; exit 1; }
/usr/bin/python3 - "$tmp/f.xdmf" "$tmp/f.json" <<'PY' || fail=1
import json, sys
import meshio, numpy as np
m = meshio.read(sys.argv[1])
summary = json.load(open(sys.argv[2]))
expected = {"displacement": 3, "stress": 9, "von_mises": 1, "max_shear": 1, "contact_pressure": 1}
assert set(m.point_data) == set(expected), sorted(m.point_data)
for name, width in expected.items():
    a = m.point_data[name]
    assert a.dtype == np.float64, (name, a.dtype)
    assert a.shape[0] == len(m.points) and (a.size // len(m.points)) == width, (name, a.shape)
assert [c.type for c in m.cells] == ["tetra"], [c.type for c in m.cells]
assert m.cells[0].data.max() < len(m.points)
peak = m.point_data["contact_pressure"].max()
assert abs(peak / summary["p_max_nodal_pa"] - 1) < 1e-12, (peak, summary["p_max_nodal_pa"])
assert np.abs(m.point_data["displacement"]).max() > 0
print(f"meshio: {len(m.points)} nodes, {len(m.cells[0].data)} tetrahedra, every field float64, peak {peak:.6g} Pa")
PY
# Refused up front: no solve, nothing written.
"$bin" -q hertz --model axi --xdmf "$tmp/missing/f.xdmf" > "$tmp/bad.log" 2>&1; rc=$?
if [[ $rc -ne 2 ]] || ! grep -q "missing" "$tmp/bad.log"; then echo "FAIL: missing folder gave $rc"; cat "$tmp/bad.log"; fail=1; fi
exit $fail
