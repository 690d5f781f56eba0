#!/usr/bin/env bash
# Field output of `rollcheck hertz --xdmf` (docs/guide/fields.md), written by
# DOLFINx's XDMFFile: NAME.xdmf with its data in NAME.h5 beside it, one step
# per load-control solve, numbered 1, 2, ..., every field in each step. Read back with Debian's python3-meshio
# TimeSeriesReader: the 3D solve (on two ranks, so gathered from both) is a
# time series of at least two load steps; the last step agrees with the run's
# JSON summary (peak pressure, the prescribed approach on the loaded face, von
# Mises from the stress); the axisymmetric stress is in the mesh's axes
# (r, z, theta), so on the axis, where sigma_rr = sigma_theta theta, its XX
# and ZZ components agree. A missing output folder and a write patience that
# is no whole number of seconds are refused before any computation; no
# scratch is left behind.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for model in axi 3d; do
  # 3D: the default P2, on a coarse contact zone (15k DOFs): the writer, not the accuracy, is under test.
  launch=(); mesh=(--refine 0)
  [[ $model == 3d ]] && launch=(mpirun -n 2) && mesh=(--contact-element-size 4e-5 --pole-refine 0 --edge-refine 0)
  "${launch[@]}" "$bin" -q hertz --model $model "${mesh[@]}" --xdmf "$tmp/$model.xdmf" --json "$tmp/$model.json" > /dev/null \
    || { echo "FAIL: $model run"; fail=1; continue; }
  check '[[ -s $tmp/$model.h5 ]]' "$model: no HDF5 data beside the XDMF file"
  /usr/bin/python3 - "$tmp/$model.xdmf" "$tmp/$model.json" <<'PY' || fail=1
import json, sys
import meshio
import numpy as np
j = json.load(open(sys.argv[2]))
three_d = j["model"] == "3d"
with meshio.xdmf.TimeSeriesReader(sys.argv[1]) as reader:
    points, cells = reader.read_points_cells()
    steps = [reader.read_data(k) for k in range(reader.num_steps)]
assert len(steps) >= (2 if three_d else 1), f"{len(steps)} load steps"
times = [t for t, _, _ in steps]
assert times == list(range(1, len(steps) + 1)), times
assert open(sys.argv[1]).read().count('Format="HDF"') > 0, "the data are not in the HDF5 file"
n = len(points)
expected = {"displacement": 3, "stress": 9, "von_mises": 1, "max_shear": 1, "contact_pressure": 1}
for t, point_data, _ in steps:
    assert set(point_data) == set(expected), sorted(point_data)
field = {}
for name, width in expected.items():
    a = steps[-1][1][name]
    assert a.dtype == np.float64, (name, a.dtype)
    assert a.size == n * width, (name, a.shape)
    field[name] = a.reshape(n, width)
assert [c.type for c in cells] == (["tetra"] if three_d else ["triangle"]), [c.type for c in cells]
p = field["contact_pressure"].ravel()
assert abs(p.max() - j["p_max_nodal_pa"]) <= 1e-12 * j["p_max_nodal_pa"], (p.max(), j["p_max_nodal_pa"])
# The loaded face (top, z = R) moved down by the prescribed approach.
z = points[:, 2 if three_d else 1]
top = np.isclose(z, j["radius_m"], rtol=0, atol=1e-12)
uz = field["displacement"][:, 2 if three_d else 1]
assert top.any() and np.allclose(uz[top], -j["approach_m"], rtol=1e-9, atol=0), (uz[top].min(), j["approach_m"])
# The stress is symmetric and von Mises follows from it.
s = field["stress"].reshape(n, 3, 3)
assert np.allclose(s, s.transpose(0, 2, 1), atol=1e-6 * np.abs(s).max())
dev = s - np.trace(s, axis1=1, axis2=2)[:, None, None] / 3 * np.eye(3)
vm = np.sqrt(1.5 * (dev * dev).sum(axis=(1, 2)))
assert np.allclose(vm, field["von_mises"].ravel(), rtol=1e-9, atol=1e-9 * vm.max())
if not three_d:
    # (r, z, theta): on the axis sigma_rr = sigma_theta theta (XX = ZZ), while sigma_zz (YY) differs.
    axis = np.isclose(points[:, 0], 0, atol=1e-12) & (np.abs(s).max(axis=(1, 2)) > 0.05 * np.abs(s).max())
    hoop_gap = np.abs(s[axis, 0, 0] - s[axis, 2, 2]).mean()
    vertical_gap = np.abs(s[axis, 0, 0] - s[axis, 1, 1]).mean()
    assert axis.sum() > 3 and hoop_gap < 0.05 * vertical_gap, (axis.sum(), hoop_gap, vertical_gap)
print(f"{j['model']}: {n} nodes, {len(cells[0].data)} cells, {len(steps)} load steps, 5 fields each")
PY
done
"$bin" -q hertz --model axi --xdmf "$tmp/missing/f.xdmf" > "$tmp/bad.log" 2>&1; rc=$?
if [[ $rc -ne 2 ]] || ! grep -q "missing" "$tmp/bad.log"; then echo "FAIL: a missing folder gave exit $rc"; cat "$tmp/bad.log"; fail=1; fi
ROLLCHECK_WRITE_PATIENCE=1.5 "$bin" -q hertz --model axi --xdmf "$tmp/patience.xdmf" > "$tmp/bad.log" 2>&1; rc=$?
if [[ $rc -ne 2 ]] || ! grep -q "ROLLCHECK_WRITE_PATIENCE" "$tmp/bad.log" || [[ -e $tmp/patience.xdmf ]]; then
  echo "FAIL: a write patience of 1.5 s gave exit $rc"; cat "$tmp/bad.log"; fail=1
fi
ls -A "$tmp" | grep -q '\.tmp' && { echo "FAIL: scratch left behind"; fail=1; }
exit $fail
