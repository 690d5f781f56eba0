#!/usr/bin/env bash
# Regenerates docs/results/hertz.md: the penalty, convergence and pointwise
# studies (scripts/studies/hertz_studies.sh, one rank) and the defaults' runs
# (scripts/studies/hertz_defaults.sh), every JSON under OUT_DIR (default
# results/hertz); then scripts/studies/hertz_page.py writes the page from
# those files alone.
# Usage: scripts/studies/hertz.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/hertz}
ROLLCHECK=$bin bash "$here/scripts/studies/hertz_studies.sh" "$out" 1
bash "$here/scripts/studies/hertz_defaults.sh" "$bin" "$out"
/usr/bin/python3 "$here/scripts/studies/hertz_page.py" "$out" "$("$bin" --version | head -1)" \
  > "$here/docs/results/hertz.md"
