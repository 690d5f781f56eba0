#!/usr/bin/env bash
# Field output of `rollcheck hertz --xdmf`: ONE self-contained XDMF file per
# solve, read back with Debian's python3-meshio: one grid, every field on its
# nodes in float64, agreeing with the run's JSON summary (peak pressure, the
# prescribed approach on the loaded face, von Mises from the stress). The 3D
# solve runs on two ranks, so the file is gathered from both. An output path
# whose folder is missing is refused before any computation; no scratch is
# left behind.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for model in axi 3d; do
  launch=(); [[ $model == 3d ]] && launch=(mpirun -n 2)
  "${launch[@]}" "$bin" -q hertz --model $model --refine 0 --xdmf "$tmp/$model.xdmf" --json "$tmp/$model.json" \
    || { echo "FAIL: $model run"; fail=1; continue; }
  [[ -e $tmp/$model.h5 ]] && { echo "FAIL: $model wrote a side file"; fail=1; }
  /usr/bin/python3 - "$tmp/$model.xdmf" "$tmp/$model.json" <<'PY' || fail=1
import json, sys
import meshio
import numpy as np
m = meshio.read(sys.argv[1])
j = json.load(open(sys.argv[2]))
three_d = j["model"] == "3d"
n = len(m.points)
expected = {"displacement": 3, "stress": 9, "von_mises": 1, "max_shear": 1, "contact_pressure": 1}
assert set(m.point_data) == set(expected), sorted(m.point_data)
field = {}
for name, width in expected.items():
    a = m.point_data[name]
    assert a.dtype == np.float64, (name, a.dtype)
    assert a.size == n * width, (name, a.shape)
    field[name] = a.reshape(n, width)
assert [c.type for c in m.cells] == (["tetra"] if three_d else ["triangle"]), [c.type for c in m.cells]
assert 0 <= m.cells[0].data.min() and m.cells[0].data.max() < n
p = field["contact_pressure"].ravel()
assert abs(p.max() - j["p_max_nodal_pa"]) <= 1e-12 * j["p_max_nodal_pa"], (p.max(), j["p_max_nodal_pa"])
# The loaded face (top, z = R) moved down by the prescribed approach.
z = m.points[:, 2 if three_d else 1]
top = np.isclose(z, j["radius_m"], rtol=0, atol=1e-12)
uz = field["displacement"][:, 2 if three_d else 1]
assert top.any() and np.allclose(uz[top], -j["approach_m"], rtol=1e-9, atol=0), (uz[top].min(), j["approach_m"])
# The stress is symmetric and von Mises follows from it.
s = field["stress"].reshape(n, 3, 3)
assert np.allclose(s, s.transpose(0, 2, 1), atol=1e-6 * np.abs(s).max())
dev = s - np.trace(s, axis1=1, axis2=2)[:, None, None] / 3 * np.eye(3)
vm = np.sqrt(1.5 * (dev * dev).sum(axis=(1, 2)))
assert np.allclose(vm, field["von_mises"].ravel(), rtol=1e-9, atol=1e-9 * vm.max())
print(f"{j['model']}: {n} nodes, {len(m.cells[0].data)} cells, 5 fields in float64 from one file")
PY
done
"$bin" -q hertz --model axi --xdmf "$tmp/missing/f.xdmf" > "$tmp/bad.log" 2>&1; rc=$?
if [[ $rc -ne 2 ]] || ! grep -q "missing" "$tmp/bad.log"; then echo "FAIL: a missing folder gave exit $rc"; cat "$tmp/bad.log"; fail=1; fi
ls -A "$tmp" | grep -q '\.tmp' && { echo "FAIL: scratch left behind"; fail=1; }
exit $fail
