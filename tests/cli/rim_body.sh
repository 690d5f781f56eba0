#!/usr/bin/env bash
# rollcheck rim --body: every loaded rim end of a body's loop. The cylinder's
# generators run rim to rim, so every sample loads two square ends
# (90 deg): on the rigid plane not singular, each direct end's ratio agrees
# with the end table's (the same q and R), and the end-aware FEM-SDS is a
# number; bad settings exit 2 and write nothing. Two edge levels (the
# default three), the fewest that measure the ends' convergence. The
# cylinder rolls straight with N = m g through its middle, so the three load
# rules (--each-load-rule) load it alike: the same ends, ratios and scores.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
mpirun -n 2 --oversubscribe "$bin" -q rim --body cylinder --orientations 1 --samples-per-loop 256 --levels 2 \
  --each-load-rule --fem-slices 3 --json "$tmp/cylinder.json" > "$tmp/cylinder.log" 2>&1 \
  || { echo "FAIL: rim --body cylinder"; cat "$tmp/cylinder.log"; exit 1; }
check_json "two loaded square ends per sample, none singular on the rigid plane" \
  '.loop_scores.loaded_ends == 512 and .loop_scores.loaded_end_samples == 256 and .singular_from_deg > 89.999
   and (.ends | length) == 2 and all(.ends[]; .singular == false and (.interior_angle_deg - 90 | fabs) < 1e-6)' \
  "$tmp/cylinder.json"
check_json "the orientation solved directly has the asked 3 slices" \
  '(.interior.per_orientation | length) == 1 and (.interior.per_orientation[0].slices | length) == 3' "$tmp/cylinder.json"
check_json "a rim square to the ruling: its dihedral angle is its section, 90 deg, with a wedge exponent of 0 at both" \
  'all(.ends[]; (.dihedral_angle_deg - 90 | fabs) < 1e-6 and .dihedral_wedge_exponent == 0 and .section_wedge_exponent == 0)
   and (.loaded_end_dihedral_min_deg - 90 | fabs) < 1e-6 and (.loaded_end_dihedral_max_deg - 90 | fabs) < 1e-6
   and .dihedral_minus_section_exponent_max == 0' "$tmp/cylinder.json"
check_json "the square ends converge below the interior (a free end is softer), and the table (same q, R) agrees with them within 3 %" \
  'all(.ends[]; .converged and .end_to_interior < 1 and .end_peak_over_interior_peak < 1)
   and (.end_table | length) == 1 and .end_table_vs_direct < 0.03' "$tmp/cylinder.json"
check_json "end-aware FEM-SDS is a number with its status, beside the interior's" \
  '(.loop_scores.end_aware[0].fem_sds.value | type) == "number" and (.loop_scores.fem_sds_rulings.value | type) == "number"
   and (.end_aware_status | type) == "string"' "$tmp/cylinder.json"
check_json "the default load rule is the dynamic one, and the three rules agree on the cylinder" \
  '.load_rules as $r | .load_rule == "dynamic" and ([$r[].load_rule] == ["dynamic", "static", "uniform"])
   and all($r[]; .loaded_ends == 512 and (.loop_end_to_interior / $r[0].loop_end_to_interior - 1 | fabs) < 1e-9
     and (.end_aware_fem_sds / $r[0].end_aware_fem_sds - 1 | fabs) < 1e-9)' "$tmp/cylinder.json"
# Under the dynamic rule fem-sds did not solve the orientation's own ruling:
# the summary's end peak over the orientation's peak is "-", not a ratio over 0.
check '! grep -qw inf "$tmp/cylinder.log"' "the summary divides by an unknown orientation's peak"
refuses rim "--body sphere:sphere not in" "--body cylinder --end-table-step 0:end_table_step_deg" \
  "--body cylinder --end-table-radius-step 0.5:end_table_radius_step" \
  "--body cylinder --end-table-acute-step -5:end_table_acute_step_deg" \
  "--body cylinder --block-depth 4:block_depth" "--body cylinder --orientations 0:orientations" \
  "--body cylinder --fem-slices 1:fem_slices"
exit $fail
