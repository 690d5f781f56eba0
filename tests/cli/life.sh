#!/usr/bin/env bash
# `rollcheck life`: the JSON the life study promises (the FEM slice's
# subsurface stress against the closed form, the load-life exponent against
# the derived one, the comparison records with their verdicts), its Markdown
# table, and bad input refused before computing.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
# A coarse run: the keys, the checks and the verdicts' form, not converged ratios.
"$bin" -q life --samples-per-loop 400 --pieces 4 --refines 2 4 --json "$tmp/l.json" --markdown "$tmp/l.md" \
  || { echo "FAIL: life run"; fail=1; }
check_json "the FEM slice's largest shear within 1 % of 0.300 p0 at 0.786 b" \
  '(.subsurface.fem_max_shear_over_p0 / 0.300 - 1 | fabs) < 0.01 and (.subsurface.fem_max_shear_depth_over_b / 0.786 - 1 | fabs) < 0.01' \
  "$tmp/l.json"
check_json "the FEM slice's orthogonal shear within 1 % of 0.250 p0" \
  '(.subsurface.fem_orthogonal_shear_over_p0 / 0.250 - 1 | fabs) < 0.01' "$tmp/l.json"
check_json "the loop quadrature's convergence: the oloid / cylinder life at each load, at half the quadrature too" \
  '(.quadrature_convergence | length) == 3 and ([.quadrature_convergence[] | .oloid_over_cylinder_life > 0 and .oloid_over_cylinder_life_half_quadrature > 0 and (.change | type) == "number"] | all)' \
  "$tmp/l.json"
check_json "the measured load-life exponent within 2 % of the derived" \
  '.load_life_exponent_derived == 4 and (.load_life_exponent / .load_life_exponent_derived - 1 | fabs) < 0.02' \
  "$tmp/l.json"
check_json "three loads, the third the cylinder's 1.5 GPa load" \
  '(.loads_n | length) == 3 and .loads_n[0] == 100 and .loads_n[1] == 5000 and .loads_n[2] > 1e8' "$tmp/l.json"
check_json "every comparison record has its fields" \
  '[.comparisons[] | has("name") and has("bodies") and has("life_ratio_min") and has("life_ratio_max") and has("verdict") and has("flips")] | all' \
  "$tmp/l.json"
check_json "the oloid is compared with the cylinder" \
  '[.comparisons[] | select(.name == "oloid vs cylinder")] | length == 12' "$tmp/l.json"
check_json "a verdict is robust or names its choices" \
  '[.comparisons[].verdict | test("^(robust|depends on [a-z_, ]+|cannot be tested)$")] | all' "$tmp/l.json"
check_json "the oloid is compared with the preprint's body and the family's best" \
  '[.comparisons[].name] | (index("oloid vs paper-oloid") != null and index("oloid vs u-optimum") != null and index("oloid vs fem-sds-optimum") != null)' "$tmp/l.json"
check_json "a comparison that cannot be tested says why; one that can does not" \
  '[.comparisons[] | (.verdict == "cannot be tested") == (.untested_because != null)] | all' "$tmp/l.json"
check_json "Ioannides-Harris at 100 N: both lives infinite below the fatigue limit" \
  '[.comparisons[] | select(.model == "ioannides_harris" and .load_n == 100) | .untested_because | test("fatigue limit")] | all' "$tmp/l.json"
check_json "a range is over the cells where it is defined, at most the grid's" \
  '[.comparisons[] | .cells <= .grid_cells and .grid_cells == 45] | all' "$tmp/l.json"
check_json "rim ends: every body at every load, the life with the ends at most the life without" \
  '(.rims.lives | length) == 15 and ([.rims.lives[] | select(.rows | length > 0) | .rows[] | .life_with_over_without_ends > 0 and .life_with_over_without_ends <= 1] | all)' "$tmp/l.json"
check_json "rim ends: the end/interior ratio falls as the edge is rounded" \
  '[.rims.lives[] | select(.body == "oloid") | [.rows[].end_over_interior] | . == (sort | reverse)] | all' "$tmp/l.json"
grep -q '^| oloid vs cylinder | 100 |' "$tmp/l.md" || { echo "FAIL: no Markdown row"; fail=1; }
grep -q '^| oloid | 100 | ' "$tmp/l.md" || { echo "FAIL: no Markdown row of the rim ends"; fail=1; }
"$bin" -q life --markdown /nonexistent/l.md > /dev/null 2> "$tmp/err.txt"; code=$?
[[ $code -eq 2 ]] || { echo "FAIL: bad --markdown path gave exit $code"; fail=1; }
grep -q -- '--markdown' "$tmp/err.txt" || { echo "FAIL: the message does not name --markdown"; fail=1; }
refuses life '--samples-per-loop 1:samples-per-loop' '--refines 20:refines' '--end-ratios /nonexistent.json:end-ratios'
"$bin" -q life --edge-radii 0.04 0.01 > /dev/null 2> "$tmp/err2.txt"; code=$?
[[ $code -eq 2 ]] && grep -q -- '--edge-radii' "$tmp/err2.txt" || { echo "FAIL: descending --edge-radii gave exit $code"; fail=1; }
exit $fail
