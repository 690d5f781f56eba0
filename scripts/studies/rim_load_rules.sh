#!/usr/bin/env bash
# The rounded rims under each load rule (docs/results/rims.md, "The rounded
# rims under each load rule"): the oloid's loop and the cylinder's, r1 =
# 10 mm, F = 800 N, r_e = 0.4 mm on the rigid plane, each scored under the
# static, dynamic and uniform load rules in one run (`rollcheck rim --body B
# --load-rule static --each-load-rule`, two ranks; the tables shared by the
# rules), then the page's section between its markers
# (scripts/studies/rim_load_rules_page.py). Each body's settings are cheap
# ones (coarse edge elements, 1024 samples, one orientation, one column of
# the end table) whose end-aware status the page reports; OLOID and CYLINDER
# override them.
# Usage: scripts/studies/rim_load_rules.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/rim_load_rules}
mkdir -p "$out"
common="--radius 0.01 --load 800 --edge-radius 4e-4 --load-rule static --each-load-rule"
declare -A settings=(
  [oloid]=${OLOID:---samples-per-loop 1024 --orientations 1 --levels 2 --edge-element 0.125 --end-table-step 60 --end-table-radius-step 0}
  [cylinder]=${CYLINDER:---samples-per-loop 1024 --orientations 1 --levels 2 --edge-element 0.03125 --end-table-step 30 --end-table-radius-step 0})
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
for body in oloid cylinder; do
  start=$(date +%s)
  # shellcheck disable=SC2086  # the settings are words
  mpirun -n 2 --oversubscribe "$bin" -q rim --body "$body" $common ${settings[$body]} \
    --json "$out/$body.json" > "$out/$body.log" 2>&1 \
    || { echo "rim --body $body failed: see $out/$body.log" >&2; exit 1; }
  echo "$body: $(( $(date +%s) - start )) s" >&2
done
/usr/bin/python3 "$here/scripts/studies/rim_load_rules_page.py" "$out/oloid.json" "$out/cylinder.json" \
  "$("$bin" --version | head -1)" "$common" "${settings[oloid]}" "${settings[cylinder]}" \
  "$here/docs/results/rims.md"
