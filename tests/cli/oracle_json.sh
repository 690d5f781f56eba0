#!/usr/bin/env bash
# `rollcheck oracle` JSON: the keys the issue lists, null for scores not asked
# for, per-face arrays with --per-face, the reference's values in
# paper-compatible mode; a case file runs the same scene; `rollcheck search`
# writes JSON and HDF5.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
oloid=$source/meshes/reference/oloid_reference.obj
ref=$source/tests/data/reference/reference_outputs.json
"$bin" -q oracle --mesh "$oloid" --paper-compat --per-face --json "$tmp/rigid.json" || { echo "FAIL: rigid run"; fail=1; }
for key in cds sds tds wds_vol wds_depth fds mean_peak_pressure_pa stress_cv n_faces n_samples wall_s; do
  check_json "key $key present" "has(\"$key\")" "$tmp/rigid.json"
done
check_json "n_faces" '.n_faces == 1198' "$tmp/rigid.json"
check_json "n_samples" '.n_samples == 600' "$tmp/rigid.json"
check_json "per-face arrays" '(.per_face.contact_counts | length) == 1198 and (.per_face.stress_pa | length) == 1198' "$tmp/rigid.json"
cds_ref=$(jq '.geometries.oloid.rigid.cds' "$ref")
check_json "rigid CDS as the reference" "((.cds - $cds_ref) | fabs) < 1e-12 * $cds_ref" "$tmp/rigid.json"
"$bin" -q oracle --mesh "$oloid" --paper-compat --oracle approx --metrics cds --json "$tmp/approx.json" || { echo "FAIL: approx run"; fail=1; }
check_json "scores not asked for are null" '.sds == null and .tds == null and .wds_vol == null and .fds == null' "$tmp/approx.json"
approx_ref=$(jq '.geometries.oloid.approx.cds' "$ref")
check_json "approximate CDS as the reference" "((.cds - $approx_ref) | fabs) < 1e-9 * $approx_ref" "$tmp/approx.json"
# The case file runs the same scene; --set overrides a key.
"$bin" -q run "$(dirname "$0")/../../cases/oracle_reference_oloid.toml" --set mesh_file="$oloid" --set oracle=approx \
  --set metrics=cds --json "$tmp/case.json" || { echo "FAIL: case file"; fail=1; }
check_json "case file gives the same CDS" "((.cds - $approx_ref) | fabs) < 1e-9 * $approx_ref" "$tmp/case.json"
# Search: JSON and HDF5, ranks 1..n among valid genomes.
"$bin" -q search --grid quick --paper-compat --validate-top 2 --json "$tmp/search.json" --hdf5 "$tmp/search.h5" > "$tmp/table.txt" 2>&1 \
  || { echo "FAIL: search"; fail=1; }
check_json "search genomes" '(.genomes | length) == 45 and .n_validated == 2' "$tmp/search.json"
check_json "approximate ranks" '[.genomes[].approximate.rank] | sort == [range(1; 46)]' "$tmp/search.json"
[[ -s "$tmp/search.h5" ]] || { echo "FAIL: no HDF5 file"; fail=1; }
grep -q "approx CDS" "$tmp/table.txt" || { echo "FAIL: no ranked table"; fail=1; }
# The table goes to the log: with --json - stdout is JSON alone (the audit reads it).
"$bin" -q search --grid quick --paper-compat --validate-top 2 --json - 2> /dev/null | jq -e '.genomes | length == 45' > /dev/null \
  || { echo "FAIL: search --json - is not JSON alone"; fail=1; }
exit $fail
