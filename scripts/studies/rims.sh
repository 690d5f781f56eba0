#!/usr/bin/env bash
# Regenerates docs/results/rims.md: the sharp rims over whole loops (`rollcheck
# rim --body B --orientations 1 --levels 2`, the audit's runs, on the rigid
# plane) for the oloid and the cylinder, every JSON and log under OUT_DIR
# (default results/rims); scripts/studies/rims_page.py writes the page from
# them, keeping the load-rule section that scripts/studies/rim_load_rules.sh
# writes between its markers (a run of its own, longer than this one).
# Usage: scripts/studies/rims.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/rims}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
loop="--orientations 1 --levels 2"
for body in oloid cylinder; do
  start=$(date +%s)
  # shellcheck disable=SC2086  # the options are words
  mpirun -n 2 --oversubscribe "$bin" -q rim --body "$body" $loop --json "$out/${body}_rigid.json" \
    > "$out/${body}_rigid.log" 2>&1 || { echo "rim --body $body failed: see $out/${body}_rigid.log" >&2; exit 1; }
  echo "$body: $(( $(date +%s) - start )) s" >&2
done
/usr/bin/python3 "$here/scripts/studies/rims_page.py" "$out" "$loop" "$("$bin" --version | head -1)" \
  "$here/docs/results/rims.md"
