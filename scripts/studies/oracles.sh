#!/usr/bin/env bash
# Regenerates docs/results/oracles.md: the preprint's quick search in
# paper-compatible mode (`rollcheck search --grid quick --paper-compat`, and
# with `--matched-resolution`), the paper-compat quirk table of the reference
# meshes (scripts/studies/quirk_table.sh) and the approximate oracle with its
# grounding quirk corrected, every JSON under OUT_DIR (default
# results/oracles); then scripts/studies/oracles_page.py writes the page from
# those files alone.
# Usage: scripts/studies/oracles.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/oracles}
meshes=$here/meshes/reference
mkdir -p "$out"
"$bin" -q search --grid quick --paper-compat --json "$out/search.json" > /dev/null
"$bin" -q search --grid quick --paper-compat --matched-resolution --json "$out/search_matched.json" > /dev/null
bash "$here/scripts/studies/quirk_table.sh" "$bin" "$meshes" "$out" > /dev/null
for body in oloid cylinder; do
  "$bin" -q oracle --oracle approx --paper-compat --mesh "$meshes/${body}_reference.obj" \
    --json "$out/approx_${body}.json" > /dev/null
  "$bin" -q oracle --oracle approx --paper-compat --quirks ground_at_lowest_centroid=corrected \
    --mesh "$meshes/${body}_reference.obj" --json "$out/approx_${body}_grounded.json" > /dev/null
done
/usr/bin/python3 "$here/scripts/studies/oracles_page.py" "$out" "$("$bin" --version | head -1)" \
  > "$here/docs/results/oracles.md"
