#!/usr/bin/env bash
# The results store's record schema (src/io/result_fields.h), read with h5py
# from the store a batch wrote: units from the declared fields (m/s, 1/m,
# 1/m^2, not the key's last word), an empty hertz `flags` list as an empty
# string dataset, `parameters/body` naming the mesh file a case read (with its
# SHA-256), and the `convergence/*` tables' column names.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; src=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
cp "$src/meshes/reference/oloid_reference.obj" "$tmp/body.obj"
# The rigid-body oracle (sliding speeds) on a mesh file, one short run.
cat > "$tmp/on_mesh.toml" << 'TOML'
[scene]
kind = "oracle"
mesh_file = "body.obj"
oracle = "rigid"
runs = 1
duration_s = 2.0
convergence_every = 10
TOML
cp "$src/cases/hertz_hemisphere_axisymmetric.toml" "$tmp/hertz.toml"
expect 0 "" -- "$bin" -q batch "$tmp/on_mesh.toml" "$tmp/hertz.toml" -j 1 --out "$tmp/out"
/usr/bin/python3 - "$tmp/out/results.h5" "$tmp/body.obj" "$src/postprocess" << 'PY' || fail=1
import hashlib, sys
import h5py
import numpy as np
sys.path.insert(0, sys.argv[3])
import rollcheck_store
ok = True
def need(condition, what):
    global ok
    if not condition:
        print("FAIL:", what); ok = False
with h5py.File(sys.argv[1], "r") as f:
    oracle, hertz = f["cases/on_mesh"], f["cases/hertz"]
    units = lambda case, key: case["summary/" + key].attrs.get("units")
    for key, unit in [("sliding/max_speed_m_s", "m/s"), ("sliding/mean_speed_m_s", "m/s"),
                      ("curvature/face_mean_curvature_mean_per_m", "1/m"),
                      ("curvature/face_gaussian_curvature_mean_per_m2", "1/m^2"),
                      ("curvature/effective_radius_min_m", "m"), ("mean_peak_pressure_pa", "Pa"),
                      ("wall_s", "s"), ("n_faces", "1"), ("cds", "1")]:
        need(units(oracle, key) == unit, f"{key}: units {units(oracle, key)!r}, not {unit!r}")
    flags = hertz["summary/flags"]
    need(flags.dtype.kind == "O" and flags.shape == (0,) and h5py.check_string_dtype(flags.dtype) is not None,
         f"hertz flags: {flags.dtype} {flags.shape}, not an empty string dataset")
    parameters = oracle["parameters"].attrs
    need(parameters["body"] == sys.argv[2], f"parameters/body is {parameters['body']!r}, not the mesh file")
    sha = hashlib.sha256(open(sys.argv[2], "rb").read()).hexdigest()
    need(parameters.get("mesh_file_sha256") == sha, "parameters/mesh_file_sha256 is not the mesh file's SHA-256")
    convergence = oracle["summary/convergence"]
    need(len(convergence) > 0, "no convergence tables")
    for name, table in convergence.items():
        need(table.attrs.get("columns") == "samples, score" and table.shape[1:] == (2,),
             f"convergence/{name}: columns {table.attrs.get('columns')!r}, shape {table.shape}")
# The reader of the report keeps working on the new layout.
_, cases = rollcheck_store.load_cases(sys.argv[1])
by_name = {c.name: c for c in cases}
need(list(by_name["hertz"].summary["flags"]) == [] and not isinstance(by_name["hertz"].summary["flags"], np.ndarray), f"rollcheck_store reads flags as {by_name['hertz'].summary['flags']!r}")
need(by_name["on_mesh"].units.get("sliding/max_speed_m_s") == "m/s", "rollcheck_store: units of max_speed_m_s")
need(by_name["on_mesh"].columns.get("convergence/cds") == ["samples", "score"], "rollcheck_store: columns")
need(rollcheck_store.label(by_name["on_mesh"]).startswith("on_mesh (body=" + sys.argv[2]), "label lacks the mesh file")
sys.exit(0 if ok else 1)
PY
exit $fail
