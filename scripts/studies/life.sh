#!/usr/bin/env bash
# Regenerates the life study: `rollcheck life` (the FEM slice's subsurface
# check, the load-life exponent, the bodies' L10 life ratios over the
# modelling choices); scripts/studies/life_page.py writes docs/results/life.md
# from the JSON, stamped with `rollcheck --version`.
# Usage: scripts/studies/life.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/life}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
"$bin" life --json "$out/life.json" --markdown "$out/life.md"
/usr/bin/python3 "$here/scripts/studies/life_page.py" "$out/life.json" "$("$bin" --version | head -1)" \
  > "$here/docs/results/life.md"
