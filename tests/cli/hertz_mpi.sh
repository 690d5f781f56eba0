#!/usr/bin/env bash
# MPI: 1 and 2 ranks give the same a and p0 to 1e-6 (axisymmetric with MUMPS;
# 3D with GMRES + GAMG). The default 3D hemisphere's tolerances on 2 ranks are
# hertz_mpi_default.sh (label long); serially, tests/fem/test_hertz_solid.cpp.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
mpi="mpirun -n 2 --oversubscribe"
"$bin" -q hertz --model axi --json "$tmp/axi1.json" || fail=1
$mpi "$bin" -q hertz --model axi --json "$tmp/axi2.json" || fail=1
"$bin" -q hertz --model 3d --degree 1 --refine 0 --json "$tmp/solid1.json" || fail=1
$mpi "$bin" -q hertz --model 3d --degree 1 --refine 0 --json "$tmp/solid2.json" || fail=1
[[ $fail -eq 0 ]] || { echo "FAIL: a run failed"; exit 1; }
/usr/bin/python3 - "$tmp" <<'PY'
import json, sys
d = sys.argv[1]
load = lambda name: json.load(open(f"{d}/{name}.json"))
for model in ("axi", "solid"):
    one, two = load(f"{model}1"), load(f"{model}2")
    assert one["ranks"] == 1 and two["ranks"] == 2
    for key in ("a_m", "p0_pa"):
        rel = abs(one[key] - two[key]) / abs(one[key])
        print(f"{model} {key}: 1 rank {one[key]:.12e}, 2 ranks {two[key]:.12e}, rel. diff {rel:.1e}")
        assert rel < 1e-6, (model, key, rel)
PY
