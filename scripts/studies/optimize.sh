#!/usr/bin/env bash
# Regenerates docs/results/optimize.md but its speed section
# (scripts/studies/optimize_speed.sh) and its FEM-SDS section
# (scripts/studies/optimize_fem_sds.sh), which it keeps: the searches of the
# preprint's family from its (90, 1, 1) (`rollcheck run
# cases/optimize_cds_paper.toml` local and global, resumed; `rollcheck
# optimize` under the SDS and the rigid-body oracle, each at the genome's points
# and at matched face count), the audit's title-claim searches, the rigid-body
# noise (`rollcheck oracle --quirk-table`) and the contact CV of the bodies
# found. Each run's JSON, its command (NAME.args.json) and /usr/bin/time's
# wall and CPU seconds (NAME.time.json) go to OUT_DIR (default
# results/optimize); then scripts/studies/optimize_page.py writes the page
# from those files alone.
# Usage: scripts/studies/optimize.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/optimize}
page=$here/scripts/studies/optimize_page.py
mkdir -p "$out"
export OPENBLAS_NUM_THREADS=1
run() { # NAME SUBCOMMAND OPTIONS...: `rollcheck -q SUBCOMMAND OPTIONS` with its JSON, command and times in $out
  local name=$1; shift
  printf '{"args": "%s"}\n' "$*" > "$out/$name.args.json"
  /usr/bin/time -f '{"wall_s": %e, "user_s": %U, "system_s": %S}' -o "$out/$name.time.json" \
    "$bin" -q "$@" --json "$out/$name.json" > "$out/$name.log" 2>&1 \
    || { echo "rollcheck $* failed: see $out/$name.log" >&2; exit 1; }
}
case=$here/cases/optimize_cds_paper.toml
direct=(--set method=direct-l --set max_evaluations=300)
matched=(--set matched_resolution=true)
rm -rf "$out/resume" "$out/saved"  # the resumed runs start from nothing saved
run case_local run "$case"
run case_local_faces run "$case" "${matched[@]}"
run case_direct run "$case" "${direct[@]}"
run case_direct_saved run "$case" "${direct[@]}" --set "out=$out/saved"
run case_direct_faces run "$case" "${direct[@]}" "${matched[@]}" --set "out=$out/resume"
run case_direct_faces_resumed run "$case" "${direct[@]}" "${matched[@]}" --set "out=$out/resume"
for score in sds_approx cds_rigid sds_rigid cds_rigid16 sds_rigid16; do
  read -r metric oracle <<< "${score//_/ }"
  options=(--score "$metric" --oracle "${oracle%16}" --paper-compat --points 300)
  [[ $oracle == *16 ]] && options+=(--replicates 16)
  run "$score" optimize "${options[@]}"
  run "${score}_faces" optimize "${options[@]}" --matched-resolution
done
run cds_rigid16_corrected optimize --score cds --oracle rigid --points 300 --replicates 16
# the audit's title-claim searches (row continuous_optimum; its FEM-SDS search is optimize_fem_sds.sh's)
run audit_paper optimize --score cds --oracle approx --points 300 --paper-compat
run audit_centre_line optimize --score cds --oracle approx --points 300 --paper-compat --family centre-line
run audit_corrected optimize --score cds --oracle approx --points 300
run audit_uniformity optimize --score uniformity --oracle rolling --family centre-line --points 100 \
  --max-evaluations 30
# the rigid-body oracle's spin-nudge band
run quirk_reference oracle --mesh "$here/meshes/reference/oloid_reference.obj" --quirk-table
run quirk_start oracle --body roller --points 300 --quirk-table
run quirk_start_20s oracle --body roller --points 300 --quirk-table --duration 20
run quirk_old_optimum oracle --body roller --points 300 --quirk-table --theta 97.14 --offset 0.9936 --ratio 0.7508
# the contact CV of the local search's start, optimum and lowest sweep point, and of the matched optimum
for point in case_local:start case_local:optimum case_local:sweep case_local_faces:optimum; do
  read -r theta offset ratio <<< "$(/usr/bin/python3 "$page" --genome "$out/${point%:*}.json" "${point#*:}")"
  run "cv_${point/:/_}" oracle --oracle approx --paper-compat --metrics cds --body roller --points 300 \
    --theta "$theta" --offset "$offset" --ratio "$ratio"
done
/usr/bin/python3 "$page" "$out" "$("$bin" --version | head -1)" "$here/docs/results/optimize.md"
