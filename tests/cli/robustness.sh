#!/usr/bin/env bash
# `rollcheck robustness`: the JSON the robustness study promises (the grid,
# each comparison's verdict, ratio range and flips), its Markdown table, the
# headline U comparison's flip, and an output path refused before computing.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
# A coarse loop: the keys and verdicts, not the converged values (tests/study/robustness).
"$bin" -q robustness --samples-per-loop 1000 --pieces 8 --family-samples-per-loop 500 --json "$tmp/r.json" \
  --markdown "$tmp/r.md" \
  || { echo "FAIL: robustness run"; fail=1; }
check_json "grid names each choice" \
  '.grid.rolling_energy == ["0.02","0.1","0.36","1","3","uniform_rate"] and .grid.contact_width == ["hertz","geometric"] and .grid.load_rule == ["static","dynamic","uniform"] and .grid.end_margin == ["0.02","0.05","0.1"]' \
  "$tmp/r.json"
check_json "every comparison record has its fields" \
  '[.comparisons[] | has("name") and has("score") and has("bodies") and has("verdict") and has("ratio_min") and has("ratio_max") and has("flips")] | all' \
  "$tmp/r.json"
check_json "a verdict is robust or names its choices" \
  '[.comparisons[].verdict | test("^(robust|depends on [a-z_, ]+|cannot be tested)$")] | all' "$tmp/r.json"
# With the Hertz width and the motion's own load the oloid's U falls below the
# cylinder's 0.500 near 1.36 times the barrier energy (bisected).
check_json "oloid vs cylinder U flips near energy excess 0.36" \
  '[.comparisons[] | select(.name == "oloid vs cylinder" and .score == "contact_time_u") | .flips[]
    | select(.choice == "rolling_energy" and .settings.contact_width == "hertz" and .settings.load_rule == "dynamic")
    | .value | (. > 0.3 and . < 0.42)] | (length > 0 and all)' "$tmp/r.json"
# The family: its five best at the reference cell, judged against the rest,
# and the best of them against the oloid under every score.
check_json "the family names its five best and its reference cell, one body of each mirror pair (theta, 180 - theta)" \
  '(.family.best | length) == 5 and .family.grid == "quick" and (.family.genomes | length) == 27 and .family.mirrors_merged == 18
   and ([.family.genomes[] as $a | .family.genomes[] | select(.theta_deg + $a.theta_deg == 180 and .theta_deg != 90 and .offset == $a.offset and .ratio == $a.ratio)] | length == 0)
   and .family.reference_cell == {"rolling_energy":"0.1","contact_width":"geometric","load_rule":"dynamic","end_margin":"0.05"}' \
  "$tmp/r.json"
check_json "the five best are judged against the rest" \
  '[.comparisons[] | select(.name == "the quick grid'"'"'s 5 best" and .score == "accumulated_pressure_whole")] | length == 1' \
  "$tmp/r.json"
check_json "the best genome is compared with the oloid under every score" \
  '. as $j | [.comparisons[] | select(.name == "quick-grid best vs oloid")] | length == ($j.scores | length)' "$tmp/r.json"
grep -q '^| oloid vs cylinder | contact_time_u |' "$tmp/r.md" || { echo "FAIL: no Markdown row"; fail=1; }
# An output path that cannot be written is refused (before any rolling: the
# check comes first in the command).
"$bin" -q robustness --markdown /nonexistent/r.md > /dev/null 2> "$tmp/err.txt"; code=$?
[[ $code -eq 2 ]] || { echo "FAIL: bad --markdown path gave exit $code"; fail=1; }
grep -q -- '--markdown' "$tmp/err.txt" || { echo "FAIL: the message does not name --markdown"; fail=1; }
exit $fail
