#!/usr/bin/env bash
# `rollcheck audit --quick`: the claim table's structure (every claim, mode
# cells, verdicts from the stated set, the two verdicts `reproduced` and
# `true` with their reasons, every command cited listed in the same JSON,
# the surface-coverage claim's two answers), the Markdown table, the
# commands' outputs kept by --outputs (each holds what the audit read;
# a folder of the user's is refused),
# that numbers the audit read equal what four of its listed commands print
# when run on their own (an oracle run, a mesh run, a Hertz FEM run and a
# FEM-SDS run; timings aside), and that its paper-compatible outputs on the reference meshes are the
# published code's outputs (tests/data/reference/reference_outputs.json) to
# the digits the preprint prints. Bad input (a folder without the reference
# meshes, a claim id that is none) exits 2 and writes nothing.
# With AUDIT_CLAIMS=ID,... (audit_claims.sh, the default suite's) it audits
# only those claims (`--claims`) and checks what they cite; the whole table
# takes minutes and carries the label long.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
meshes=$source/meshes/reference
claims=()
[[ -n ${AUDIT_CLAIMS:-} ]] && claims=(--claims "$AUDIT_CLAIMS")
"$bin" -q audit --quick --reference-meshes "$meshes" "${claims[@]}" --json "$tmp/audit.json" --markdown "$tmp/audit.md" \
  --outputs "$tmp/outputs" > "$tmp/stdout.md" || { echo "FAIL: audit run"; exit 1; }
j=$tmp/audit.json
want=30
[[ -n ${AUDIT_CLAIMS:-} ]] && want=$(tr ',' '\n' <<< "$AUDIT_CLAIMS" | wc -l)
# has_claim ID: whether the run audited claim ID.
has_claim() { [[ $(jq --arg id "$1" '[.claims[].id] | index($id) != null' "$j") == true ]]; }
check_json "$want claims" ".claims | length == $want" "$j"
[[ -n ${AUDIT_CLAIMS:-} ]] && check_json "the claims asked for" \
  "[.claims[].id] == [$(sed 's/[^,]*/"&"/g' <<< "$AUDIT_CLAIMS")]" "$j"
check_json "seven modes, paper-compatible first, fatigue life last" '(.modes | length) == 7 and .modes[0].mode == "paper-compatible" and .modes[6].mode == "fatigue life"' "$j"
if [[ -z ${AUDIT_CLAIMS:-} ]]; then
  check_json "the FDS claims and fixed_loci have a fatigue-life cell read from rollcheck life" \
    '([.commands[] | select(.command | startswith("rollcheck life ")) | .id]) as $l | [.claims[] | select(.id == "fatigue" or .id == "fatigue_values" or .id == "all_metrics" or .id == "fixed_loci") | .recomputations["fatigue life"] | .built and .commands == $l and (.value | length > 0)] | length == 4 and all' "$j"
fi
check_json "verdicts over the modes from the stated set" \
  '[.claims[].verdict] | all(. == "holds" or . == "holds only in paper-compatible mode" or . == "does not hold" or . == "cannot be tested" or . == "not built yet")' "$j"
check_json "verdict rules stated" '(.verdict_rules | length) >= 4 and ([.claims[].rule] | all(length > 0))' "$j"
check_json "every built cell cites known commands" \
  '([.commands[].id]) as $ids | [.claims[].recomputations[] | select(.applicable and .built) | (.commands | length > 0) and all(.commands[]; . as $c | $ids | index($c) != null)] | all' "$j"
check_json "every command a cell or a verdict cites is in the command list" \
  '([.commands[].id]) as $ids | [.claims[] | (.recomputations[].commands[], .reproduced.commands[], .true.commands[])] | all(. as $c | $ids | index($c) != null)' "$j"
check_json "reproduced: a verdict of the stated set and a reason" \
  '[.claims[].reproduced] | all((.verdict == "reproduced" or .verdict == "not reproduced" or .verdict == "cannot be tested") and (.reason | length > 0))' "$j"
check_json "true: a verdict of the stated set and a reason" \
  '[.claims[].true] | all((.verdict == "holds" or .verdict == "does not hold" or .verdict == "cannot be tested" or (.verdict | startswith("depends on "))) and (.reason | length > 0))' "$j"
has_claim cds_ratio && check_json "a ranking of bodies over the choices is read from rollcheck robustness" \
  '([.commands[] | select(.command | startswith("rollcheck robustness ")) | .id]) as $r | ($r | length == 1) and ([.claims[] | select(.id == "cds_ratio") | .true.commands[]] == $r)' "$j"
has_claim surface_coverage && check_json "surface coverage: true for the oloid under real rolling, not reproduced on the preprint's body (its flat disc)" \
  '.claims[] | select(.id == "surface_coverage") | .true.verdict == "holds" and .true.mode == "real rolling" and .reproduced.verdict == "not reproduced" and (.reproduced.reason | test("257 of 1198 faces untouched.*flat disc x = 1"))' "$j"
check_json "every command is a rollcheck command printing JSON" \
  '[.commands[].command] | all(startswith("rollcheck ") and endswith(" --json -"))' "$j"
check_json "quick mode recorded" '.quick == true' "$j"
check_json "claims that cannot be tested say why" \
  '[.claims[] | select(.verdict == "cannot be tested") | .recomputations[] | select(.applicable and (.built | not)) | .untestable | length > 0] | (length > 0 and all)' "$j"
cmp -s "$tmp/audit.md" "$tmp/stdout.md" || { echo "FAIL: --markdown file differs from stdout"; fail=1; }
grep -q '^| claim | paper | paper-compatible | matched resolution | true oloid | corrected physics | real rolling | contact mechanics | fatigue life | reproduced | true |$' \
  "$tmp/audit.md" || { echo "FAIL: Markdown header"; fail=1; }
rows=$(grep -c '^| .* | \*\*\(reproduced\|not reproduced\|cannot be tested\)\*\*[^|]* | \*\*\(holds\|does not hold\|cannot be tested\|depends on [^*]*\)\*\*[^|]* |$' "$tmp/audit.md")
[[ $rows == "$want" ]] || { echo "FAIL: Markdown has $rows claim rows, want $want"; fail=1; }
grep -q '^Verdict rules:' "$tmp/audit.md" || { echo "FAIL: no verdict rules in the Markdown"; fail=1; }

# reads_match ID FILE: FILE (a JSON output of command ID) holds every value
# the audit read from ID, timings aside (an infinite value reads back null).
reads_match() {
  [[ $(jq --slurpfile a "$j" --arg id "$1" -r '
    . as $out | ($a[0].commands[] | select(.id == $id) | .reads | to_entries)
    | map(select(.key | (endswith("wall_s") or endswith("cpu_s")) | not)) | all(.key as $p | .value as $v
        | ($p | ltrimstr("/") | split("/") | map(if test("^[0-9]+$") then tonumber else . end)) as $path
        | ($out | getpath($path)) as $printed | $printed == $v or ($v == null and $printed == "inf"))' "$2" 2>&1) == true ]]
}
# --outputs kept every command's JSON as cN.json, holding each value the
# audit read from it.
check '[[ $(find "$tmp/outputs" -name "c*.json" | wc -l) -eq $(jq ".commands | length" "$j") ]]' "one kept output per command"
for id in $(jq -r '.commands[].id' "$j"); do
  reads_match "$id" "$tmp/outputs/$id.json" || { echo "FAIL: the kept $id.json lacks a value the audit read"; fail=1; }
done
"$bin" -q audit --quick --reference-meshes "$meshes" --outputs "$source" --json "$tmp/refused.json" > /dev/null 2> "$tmp/refused.err"
[[ $? == 2 ]] && grep -q -- '--outputs' "$tmp/refused.err" && [[ ! -e $tmp/refused.json ]] \
  || { echo "FAIL: --outputs into a folder of the user's files should exit 2 naming it, before computing"; fail=1; }

# Rerun the first oracle, mesh, hertz and fem-sds command (those the claims
# cite); every value the audit read must be what they print.
for kind in oracle mesh hertz fem-sds; do
  id=$(jq -r "[.commands[] | select(.command | startswith(\"rollcheck $kind \"))][0].id" "$j")
  if [[ $id == null ]]; then
    [[ -n ${AUDIT_CLAIMS:-} ]] || { echo "FAIL: no $kind command"; fail=1; }
    continue
  fi
  line=$(jq -r ".commands[] | select(.id == \"$id\") | .command" "$j")
  read -r -a argv <<< "${line#rollcheck }"
  "$bin" -q "${argv[@]}" > "$tmp/$id.json" 2> "$tmp/$id.err" || { echo "FAIL: $line"; fail=1; continue; }
  check_json "the audit read from $id" '.commands[] | select(.id == "'"$id"'") | .reads | length > 0' "$j"
  reads_match "$id" "$tmp/$id.json" || { echo "FAIL: $id \`$line\` prints other numbers than the audit read"; fail=1; }
done

# The paper-compatible outputs on the reference meshes (Hertz table,
# pressures, sigma_H, fatigue rows), as kept by --outputs, against the
# published code's outputs, to 3 digits.
for body in oloid cylinder; do
  id=$(jq -r --arg c "rollcheck oracle --mesh $meshes/${body}_reference.obj --paper-compat --json -" \
    '[.commands[] | select(.command == $c) | .id][0]' "$j")
  jq -r --slurpfile ref "$source/tests/data/reference/reference_outputs.json" --arg b "$body" '
    def digits3: if type == "number" then (. * 1e6 | log10 | floor) as $e | (. * 1e6 / pow(10; $e - 2) | round) else . end;
    . as $r | $ref[0].geometries[$b] as $g
    | [[$r.sds, $g.hertz.sds], [$r.mean_peak_pressure_pa / 1e6, $g.hertz.mean_peak_MPa],
       [$r.stress_cv, $g.hertz.stress_cv], [$r.curvature.face_mean_curvature_std_per_m, $g.hertz.H_face_std],
       [$r.fds, $g.fatigue.fds]]
    | all(.[0] != null and ((.[0] | digits3) == (.[1] | if . == "inf" or . == "Infinity" then "inf" else digits3 end)))' \
    "$tmp/outputs/$id.json" > "$tmp/$body.ref" 2>&1
  [[ $(cat "$tmp/$body.ref") == true ]] || { echo "FAIL: $body ($id) differs from reference_outputs.json to 3 digits"; fail=1; }
done

# Bad input: no reference meshes in the folder.
mkdir -p "$tmp/empty"
"$bin" -q audit --quick --reference-meshes "$tmp/empty" --json "$tmp/bad.json" --markdown "$tmp/bad.md" 2> "$tmp/bad.err"
[[ $? == 2 ]] || { echo "FAIL: missing meshes should exit 2"; fail=1; }
grep -q -- '--reference-meshes' "$tmp/bad.err" || { echo "FAIL: message should name --reference-meshes"; fail=1; }
[[ ! -e $tmp/bad.json && ! -e $tmp/bad.md ]] || { echo "FAIL: bad input wrote output"; fail=1; }
expect 2 "option --claims: no claim 'no_such_claim'; the claims are oloid_cds, " -- \
  "$bin" audit --quick --claims oloid_area,no_such_claim --json "$tmp/bad.json"
[[ ! -e $tmp/bad.json ]] || { echo "FAIL: an unknown claim wrote output"; fail=1; }
exit $fail
