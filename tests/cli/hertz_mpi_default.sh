#!/usr/bin/env bash
# MPI, label long: the default 3D hemisphere (P2 on the cap's rings, the
# touching recovery) on 2 ranks is pointwise: the largest nodal pressure and
# the profile's RMS within 0.5 % of Hertz, a and p0 too, force within 1e-4, no
# flags (the same settings serially: tests/fem/test_hertz_solid.cpp; 1 against
# 2 ranks at a coarser mesh: hertz_mpi.sh).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
mpirun -n 2 --oversubscribe "$bin" -q hertz --model 3d --json "$tmp/solid_default.json" \
  || { echo "FAIL: the default 3D run on 2 ranks"; exit 1; }
/usr/bin/python3 - "$tmp/solid_default.json" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"3d default on 2 ranks: a {100 * r['a_error']:+.3f} %, p0 {100 * r['p0_error']:+.3f} %, "
      f"nodal {100 * r['p_max_nodal_error']:+.3f} %, RMS {100 * r['profile_rms_error']:.3f} %, "
      f"force {r['force_error']:+.1e}, {r['dofs']} dofs, {r['wall_s']:.1f} s")
assert r["ranks"] == 2 and r["degree"] == 2 and r["contact_cap"] == "rings", r
assert abs(r["p_max_nodal_error"]) < 0.005 and r["profile_rms_error"] < 0.005
assert abs(r["a_error"]) < 0.005 and abs(r["p0_error"]) < 0.005 and abs(r["force_error"]) < 1e-4
assert not r["flags"], r["flags"]
PY
