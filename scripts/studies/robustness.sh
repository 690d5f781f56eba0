#!/usr/bin/env bash
# Regenerates the robustness study: `rollcheck robustness` evaluates every
# headline comparison of bodies over the modelling choices with
# resolution-free scores; postprocess/plot_robustness.py draws each ratio over
# the grid; scripts/studies/robustness_page.py writes docs/results/robustness.md
# from the JSON, stamped with `rollcheck --version`.
# Usage: scripts/studies/robustness.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/robustness}
mkdir -p "$out"
"$bin" robustness --json "$out/robustness.json" --markdown "$out/robustness.md"
/usr/bin/python3 "$here/postprocess/plot_robustness.py" "$out/robustness.json" "$here/docs/img/robustness.png"
/usr/bin/python3 "$here/scripts/studies/robustness_page.py" "$out/robustness.json" "$("$bin" --version | head -1)" \
  > "$here/docs/results/robustness.md"
