#!/usr/bin/env bash
# Regenerates the README's audit table: `rollcheck audit` recomputes every
# quantitative claim of the preprint (paper-compatible, matched resolution,
# true oloid, corrected physics, real rolling), prints the Markdown table and
# writes it with its JSON. Pass --quick (or other audit options) after the output folder.
# Usage: scripts/audit.sh [ROLLCHECK_BINARY] [OUT_DIR] [audit options...]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/audit}
mkdir -p "$out"
"$bin" audit --json "$out/audit.json" --markdown "$out/audit.md" "${@:3}"
