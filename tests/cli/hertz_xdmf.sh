#!/usr/bin/env bash
# XDMF/HDF5 field output of `rollcheck hertz --xdmf`, read back with h5py
# (Debian's /usr/bin/python3): every function is there under its name, on the
# mesh's nodes, and agrees with the run's JSON summary.
set -u
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
fail=0
for model in axi 3d; do
  "$bin" -q hertz --model $model --refine 0 --xdmf "$tmp/$model.xdmf" --json "$tmp/$model.json" \
    || { echo "FAIL: $model run"; fail=1; continue; }
  /usr/bin/python3 - "$tmp/$model.xdmf" "$tmp/$model.h5" "$tmp/$model.json" <<'PY' || fail=1
import json, sys
import xml.etree.ElementTree as ET
import h5py
import numpy as np
xdmf, h5, summary = sys.argv[1:]
j = json.load(open(summary))
names = {a.get("Name") for a in ET.parse(xdmf).iter("Attribute")}
expected = {"displacement", "stress", "von_mises", "max_shear", "contact_pressure"}
assert expected <= names, f"XDMF attributes {names}"
with h5py.File(h5, "r") as f:
    x = f["Mesh/mesh/geometry"][...]
    n = x.shape[0]
    field = {name: f[f"Function/{name}/0"][...] for name in expected}
assert field["displacement"].shape == (n, 3), field["displacement"].shape
assert field["stress"].shape == (n, 9), field["stress"].shape
for name in ("von_mises", "max_shear", "contact_pressure"):
    assert field[name].shape in ((n,), (n, 1)), (name, field[name].shape)
p = field["contact_pressure"].ravel()
assert abs(p.max() - j["p_max_nodal_pa"]) <= 1e-9 * j["p_max_nodal_pa"], (p.max(), j["p_max_nodal_pa"])
# The loaded face (top, z = R) moved down by the prescribed approach.
z = x[:, x.shape[1] - 1] if j["model"] == "3d" else x[:, 1]
top = np.isclose(z, j["radius_m"], rtol=0, atol=1e-12)
uz = field["displacement"][:, 2 if j["model"] == "3d" else 1]
assert np.allclose(uz[top], -j["approach_m"], rtol=1e-9, atol=0), (uz[top].min(), uz[top].max(), j["approach_m"])
# The stress is symmetric and von Mises follows from it.
s = field["stress"].reshape(n, 3, 3)
assert np.allclose(s, s.transpose(0, 2, 1), atol=1e-6 * np.abs(s).max())
dev = s - np.trace(s, axis1=1, axis2=2)[:, None, None] / 3 * np.eye(3)
vm = np.sqrt(1.5 * (dev * dev).sum(axis=(1, 2)))
assert np.allclose(vm, field["von_mises"].ravel(), rtol=1e-9, atol=1e-9 * vm.max())
PY
done
ls -A "$tmp" | grep -q '\.tmp' && { echo "FAIL: scratch folder left behind"; fail=1; }
exit $fail
