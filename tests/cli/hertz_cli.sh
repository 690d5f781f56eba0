#!/usr/bin/env bash
# `rollcheck hertz`: bad input exits 2 naming the input and writes nothing; a
# good run writes the issue's JSON keys; the case files run through
# `rollcheck run` with overrides. Also the command line around it: usage
# lines, an unknown subcommand, PETSc options after `--`, --version.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
here=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf "$tmp"; mkdir -p "$tmp"
expect 2 "radius.*-0.01" -- "$bin" hertz --radius -0.01 --json "$tmp/bad1.json"
expect 2 "poisson.*0.5" -- "$bin" hertz --poisson 0.5 --json "$tmp/bad2.json"
expect 2 "degree.*3" -- "$bin" hertz --degree 3 --json "$tmp/bad3.json"
expect 2 "model" -- "$bin" hertz --model 4d --json "$tmp/bad4.json"
expect 2 "load.*nan|force_n.*nan|finite" -- "$bin" hertz --load nan --json "$tmp/bad5.json"
# A refused option starts no MPI (the session puts MPI off until the
# subcommand's options are checked): with an MPI that cannot start, the
# refusal is the same, while a solve stops in MPI's start.
OMPI_MCA_pml=nonexistent expect 2 "option --radius: 'radius_m' must be > 0" -- "$bin" hertz --radius -1
OMPI_MCA_pml=nonexistent "$bin" -q hertz --model axi --json "$tmp/no_mpi.json" > /dev/null 2>&1; rc=$?
check '[[ $rc -ne 0 && ! -e "$tmp/no_mpi.json" ]]' "a solve needs MPI to start (the check above is not vacuous)"
expect 2 "xdmf" -- "$bin" hertz --xdmf "$tmp/fields.vtk" --json "$tmp/bad6.json"
expect 2 "unknown key 'wibble'" -- "$bin" run "$here/cases/hertz_cylinder.toml" --set wibble=1
expect 2 "refine.*13" -- "$bin" hertz --refine 13 --json "$tmp/bad7.json"
expect 2 "force_rtol.*0.5" -- "$bin" hertz --force-rtol 0.5 --json "$tmp/bad8.json"
expect 2 "pressure-recovery|pressure_recovery" -- "$bin" hertz --pressure-recovery smooth --json "$tmp/bad14.json"
expect 2 "edge_refine.*3d model.*axi" -- "$bin" hertz --model axi --edge-refine 2 --json "$tmp/bad15.json"
expect 2 "pole.refine.*7" -- "$bin" hertz --model 3d --pole-refine 7 --json "$tmp/bad16.json"
# One spelling per quantity: the old --E and --nu are gone.
expect 2 "unknown option '--nu'" -- "$bin" hertz --nu 0.3 --json "$tmp/bad9.json"
expect 2 "unknown option '--E'" -- "$bin" hertz --E 200e9 --json "$tmp/bad10.json"
expect 2 "unknown subcommand 'hertx'.*did you mean 'hertz'" -- "$bin" hertx --json "$tmp/bad11.json"
# A PETSc option before `--` is named, not read as -h (help, exit 0).
expect 2 "[-]hertz_ksp_type.*PETSc.*--" -- "$bin" hertz -hertz_ksp_type cg --json "$tmp/bad12.json"
expect 2 "PETSc options" -- "$bin" hertz --json "$tmp/bad13.json" -- cg
if ls -A "$tmp" | grep -q .; then echo "FAIL: output written on error:"; ls -A "$tmp"; fail=1; fi

# A good axisymmetric run: the issue's keys, with units, and no NaN.
"$bin" -q hertz --model axi --radius 0.01 --youngs-modulus 200e9 --poisson 0.3 --load 100 --degree 1 --refine 2 --penalty-c 100 \
  --json "$tmp/axi.json" || { echo "FAIL: axi run"; fail=1; }
/usr/bin/python3 - "$tmp/axi.json" <<'PY' || fail=1
import json, math, sys
j = json.load(open(sys.argv[1]))
keys = ["a_m", "a_hertz_m", "p0_pa", "p0_hertz_pa", "force_n", "dofs", "newton_its", "wall_s", "krylov_its",
        "cells", "mesh_s", "assembly_s", "solve_s", "peak_memory_mb", "approach_m", "approach_hertz_m",
        "max_shear_pa", "max_shear_depth_m", "max_von_mises_pa", "max_von_mises_depth_m", "profile", "flags",
        "p0_source", "p_max_nodal_pa", "p_max_nodal_error", "profile_rms_error", "profile_rms_error_interior",
        "pressure_recovery"]
missing = [k for k in keys if k not in j]
assert not missing, f"missing keys {missing}"
for k, v in j.items():
    assert not (isinstance(v, float) and not math.isfinite(v)), f"{k} = {v}"
assert j["model"] == "axi" and j["refine"] == 2
assert abs(j["force_n"] - 100) < 1e-2, j["force_n"]
assert len(j["profile"]["r_m"]) == len(j["profile"]["p_pa"]) > 10
# The pointwise measures beside the fit, recomputed from the profile: its RMS
# against Hertz's profile, and its largest pressure (at the axis, inside the profile).
p0 = j["p0_hertz_pa"]
rows = list(zip(j["profile"]["p_pa"], j["profile"]["p_hertz_pa"]))
rms = math.sqrt(sum(((p - h) / p0) ** 2 for p, h in rows) / len(rows))
assert abs(rms - j["profile_rms_error"]) < 1e-12, (rms, j["profile_rms_error"])
inner = [((p - h) / p0) ** 2 for r, p, h in zip(j["profile"]["r_m"], j["profile"]["p_pa"], j["profile"]["p_hertz_pa"])
         if r < 0.9 * j["a_hertz_m"]]
assert abs(math.sqrt(sum(inner) / len(inner)) - j["profile_rms_error_interior"]) < 1e-12
assert j["pressure_recovery"] == "lumped"
assert max(p for p, _ in rows) == j["p_max_nodal_pa"], j["p_max_nodal_pa"]
assert abs(j["p_max_nodal_error"] - (j["p_max_nodal_pa"] / p0 - 1)) < 1e-12
PY

# PETSc options after `--` reach the solver: CG with Jacobi instead of the 2D
# default (one LU solve per Newton iteration) takes many Krylov iterations to
# the same answer.
"$bin" -q hertz --model axi --refine 0 --json "$tmp/lu.json" || { echo "FAIL: axi LU run"; fail=1; }
"$bin" -q hertz --model axi --refine 0 --json "$tmp/cg.json" -- -hertz_ksp_type cg -hertz_pc_type jacobi \
  -hertz_ksp_rtol 1e-12 -hertz_ksp_max_it 100000 || { echo "FAIL: axi run with PETSc options"; fail=1; }
/usr/bin/python3 - "$tmp/lu.json" "$tmp/cg.json" <<'PY' || fail=1
import json, sys
lu, cg = (json.load(open(p)) for p in sys.argv[1:])
assert lu["krylov_its"] <= lu["newton_its"], (lu["krylov_its"], lu["newton_its"])
assert cg["krylov_its"] > 10 * cg["newton_its"], (cg["krylov_its"], cg["newton_its"])
assert abs(cg["a_m"] / lu["a_m"] - 1) < 1e-6, (cg["a_m"], lu["a_m"])
PY

# Usage lines name the program, not the build path; --version names the
# libraries rollcheck was built on.
"$bin" hertz --help | grep -q "^Usage: rollcheck hertz" || { echo "FAIL: usage line"; "$bin" hertz --help | head -2; fail=1; }
version=$("$bin" --version)
for pattern in "^rollcheck [0-9]+\.[0-9]+\.[0-9]+ \(commit ([0-9a-f]{7,}(-dirty)?|unknown)\)" "DOLFINx 0\.5\.2" \
  "PETSc [0-9]+\.[0-9]+\.[0-9]+" "gmsh [0-9]+\.[0-9]+\.[0-9]+"; do
  grep -qE "$pattern" <<<"$version" || { echo "FAIL: --version lacks '$pattern':"; echo "$version"; fail=1; }
done
# The commit is stamped at build time (cmake/commit_stamp.cmake): in a checkout
# it is the source's HEAD (a commit after the build, not rebuilt, fails here).
if head=$(git -C "$here" describe --always 2>/dev/null); then
  grep -qE "\(commit $head(-dirty)?\)" <<<"$version" \
    || { echo "FAIL: --version does not name HEAD $head:"; echo "$version"; fail=1; }
fi

# The case files, through `rollcheck run`, coarse for speed (the hemisphere's
# 3D default, P2 on rings, is hertz_mpi_default.sh's and test_hertz_solid's).
for case in hertz_hemisphere_axisymmetric hertz_cylinder hertz_hemisphere; do
  "$bin" -q run "$here/cases/$case.toml" --set refine=0 --set degree=1 --json "$tmp/$case.json" \
    || { echo "FAIL: $case"; fail=1; }
done
/usr/bin/python3 - "$tmp/hertz_cylinder.json" <<'PY' || fail=1
import json, sys
j = json.load(open(sys.argv[1]))
assert "b_m" in j and "b_hertz_m" in j and "a_m" not in j, sorted(j)
assert abs(j["force_per_length_n_per_m"] - 5000) < 0.05, j["force_per_length_n_per_m"]
PY
# A PETSc option no solver reads is named, not silently ignored.
expect 0 "hertz_ksp_typo cg was not used" -- "$bin" hertz --model axi --refine 0 --json "$tmp/typo.json" -- -hertz_ksp_typo cg
exit $fail
