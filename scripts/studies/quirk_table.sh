#!/usr/bin/env bash
# Regenerates the README's paper-compat quirk table: for the oloid and the
# cylinder the reference code scored (meshes/reference), the
# rigid-body scores in paper-compatible mode, the band of 1e-12 rad/s spin
# nudges, and the change of every score when each quirk alone is corrected.
# Usage: scripts/studies/quirk_table.sh [ROLLCHECK_BINARY] [REFERENCE_MESH_DIR] [JSON_OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
meshes=${2:-$here/meshes/reference}
out=${3:-}
for body in oloid cylinder; do
  json=()
  [[ -n $out ]] && json=(--json "$out/quirk_table_$body.json")
  "$bin" -q oracle --mesh "$meshes/${body}_reference.obj" --quirk-table "${json[@]}"
done
