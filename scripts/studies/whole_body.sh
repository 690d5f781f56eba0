#!/usr/bin/env bash
# Regenerates docs/results/whole-body.md: the 10 mm cylinder meshed whole
# against the reduced models (`mpirun -n 2 rollcheck whole-body`, its
# defaults), its JSON under OUT_DIR (default results/whole-body); then
# scripts/studies/whole_body_page.py writes the page from that file alone.
# The oloid's runs (9-15 minutes each on 2 idle cores) are not rerun: their
# tables are in docs/notes/whole-body-tables.md.
# Usage: scripts/studies/whole_body.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/whole-body}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
mpirun -n 2 --oversubscribe "$bin" -q whole-body --json "$out/cylinder.json" > "$out/cylinder.log" 2>&1 \
  || { echo "whole-body failed: see $out/cylinder.log" >&2; exit 1; }
/usr/bin/python3 "$here/scripts/studies/whole_body_page.py" "$out/cylinder.json" "$("$bin" --version | head -1)" \
  > "$here/docs/results/whole-body.md"
