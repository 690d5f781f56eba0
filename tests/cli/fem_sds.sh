#!/usr/bin/env bash
# rollcheck fem-sds on 2 ranks: the cylinder's FEM slices against the closed
# form p0 = sqrt((F / L) E* / (pi R)) of its uniformly loaded generator, both
# creases of every orientation reported, FEM-SDS against line-Hertz SDS, the
# table and plots written whole by `run CASE --set out=...`; the rigid oracle's
# rim-point orientations reported apart; bad input exits 2 naming the input.
# The 3D slab check is fem_sds_slab.sh (label long).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
here=$(cd "$(dirname "$0")/../.." && pwd)
mpi="mpirun -n 2 --oversubscribe"
$mpi "$bin" -q run "$here/cases/fem_sds_cylinder.toml" --set orientations=2 --set fem_slices=3 --set slab_check=0 \
  --set "out=$tmp/cylinder" --json "$tmp/cylinder.json" > "$tmp/cylinder.log" 2>&1 || { echo "FAIL: cylinder run"; cat "$tmp/cylinder.log"; fail=1; }
"$bin" -q fem-sds --body oloid --oracle rigid --orientations 3 --fem-slices 3 --json "$tmp/rigid.json" \
  > "$tmp/rigid.log" 2>&1 || { echo "FAIL: rigid-oracle run"; cat "$tmp/rigid.log"; fail=1; }
[[ $fail -eq 0 ]] || exit 1
for f in fem_sds.json table.md peaks.png profiles.png; do
  [[ -s "$tmp/cylinder/$f" ]] || { echo "FAIL: $tmp/cylinder/$f missing"; fail=1; }
done
ls -a "$tmp" | grep -q '\.tmp' && { echo "FAIL: a temporary folder was left behind"; fail=1; }
/usr/bin/python3 - "$tmp" <<'PY' || fail=1
import json, math, sys
d = sys.argv[1]
r = json.load(open(f"{d}/cylinder.json"))
E, nu, F, L, R = 200e9, 0.3, 100.0, 2.0, 1.0
p0 = math.sqrt(F / L * E / (1 - nu * nu) / (math.pi * R))
assert r["orientations"] == 2 and r["fem_solved_orientations"] == 2, r
assert r["orientations_reaching_crease"] == 2 and r["orientations_reaching_obtuse_rim"] == 0
for o in r["per_orientation"]:
    assert o["support"] == "segment" and len(o["creases"]) == 2, o["creases"]
    assert abs(o["centre_of_pressure"] - 0.5) < 1e-6
    assert abs(o["line_hertz_peak_pa"] / p0 - 1) < 1e-9, (o["line_hertz_peak_pa"], p0)
    assert abs(o["fem_peak_pa"] / p0 - 1) < 0.005, (o["fem_peak_pa"], p0)
    assert abs(o["fem_peak_refinement_change"]) < 0.03
    # Square rims: the other face at each end is the flat end disc.
    assert max(abs(v) for v in o["rim_overhang_deg"]) < 1e-6 and o["obtuse_loaded_rims"] == 0, o["rim_overhang_deg"]
    assert o["dofs"] > 0 and o["newton_iterations"] > 0 and o["wall_s"] > 0
    print(f"cylinder t = {o['time_s']:.3f} s: FEM p0 {o['fem_peak_pa']:.6g} Pa, closed form {p0:.6g} Pa, "
          f"finer {100 * o['fem_peak_refinement_change']:+.3f} %")
# Uniform pressure along the generator: FEM-SDS equals line-Hertz SDS to the FEM's accuracy,
# over every sample of the loop, converged in the table and in the samples.
assert abs(r["fem_sds"] / r["line_hertz_sds"] - 1) < 0.005, (r["fem_sds"], r["line_hertz_sds"])
assert r["samples"] == 16384 and r["singular_samples"] == 0 and r["loop"]["samples_by_contact"] == {"ruling": 16384}
assert r["converged"] and r["fem_sds_status"] == "converged", r["fem_sds_status"]
assert abs(r["fem_sds_table_change"]) < 0.01 and abs(r["fem_sds_sample_change"]) < 0.01
assert r["fem_solves"] >= r["fem_solves_half_table"] >= 2
assert len(r["fem_table"]) >= r["fem_solves"] and r["table_vs_direct_worst"] < 0.003
# The continuum value on the exact surface: r / L = 0.5 (docs/methods/fem-sds.md), resolution-free.
assert abs(r["fem_sds_continuum"] - 0.5) < 2e-4 and abs(r["line_hertz_sds_continuum"] - 0.5) < 2e-4, r["fem_sds_continuum"]
assert abs(r["fem_sds_continuum_change"]) < 0.01 and abs(r["fem_sds_continuum_table_change"]) < 0.01
assert r["fem_sds_continuum_status"] == "converged", r["fem_sds_continuum_status"]
rigid = json.load(open(f"{d}/rigid.json"))
unsolved = [o for o in rigid["per_orientation"] if not o["fem_solved"]]
assert len(unsolved) == rigid["orientations"] - rigid["fem_solved_orientations"]
for o in unsolved:
    assert o["reaches_crease"] and "fem_peak_pa" not in o, o
print(f"rigid oracle on the oloid: {len(unsolved)} of {rigid['orientations']} orientations stand on a crease")
# Its samples on a rim point are named and make the FEM and line-Hertz scores singular, not dropped.
loop = rigid["loop"]
assert rigid["singular_samples"] == loop["samples"] - loop["samples_by_contact"].get("ruling", 0) > 0, loop
assert rigid["fem_sds"] is None and rigid["line_hertz_sds"] is None and rigid["analytic_sds"] > 0
assert rigid["fem_sds_continuum"] is None  # no rolling loop
assert rigid["fem_sds_status"].startswith("singular:") and "rim point" in rigid["fem_sds_status"], rigid["fem_sds_status"]
assert rigid["orientations_standing_on_crease"] == sum(o["support"] != "segment" for o in rigid["per_orientation"])
PY
expect_input_error() { # args...; expected text
  local text=$1; shift
  "$bin" -q "$@" > "$tmp/bad.log" 2>&1; local rc=$?
  if [[ $rc -ne 2 ]] || ! grep -q -- "$text" "$tmp/bad.log"; then
    echo "FAIL: '$*' gave exit $rc without '$text':"; cat "$tmp/bad.log"; fail=1
  fi
}
expect_input_error "orientations" fem-sds --body cylinder --orientations 0
expect_input_error "samples" fem-sds --body cylinder --samples-per-loop 1
expect_input_error "tolerance" fem-sds --body cylinder --tolerance 0
expect_input_error "end_margin" fem-sds --body cylinder --end-margin 0.3
expect_input_error "load_n" fem-sds --body cylinder --load nan
expect_input_error "unknown option '--mesh'" fem-sds --mesh "$tmp/none.obj"
expect_input_error "sphere not in" fem-sds --body sphere
expect_input_error "slab_check" fem-sds --body cylinder --slab-check -1
expect_input_error "load-rule" fem-sds --body cylinder --load-rule quasi
expect_input_error "uniform_rate" fem-sds --body cylinder --time-law uniform_rate
exit $fail
