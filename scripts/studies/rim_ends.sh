#!/usr/bin/env bash
# Regenerates docs/results/rim-ends.md: single rim end models (`rollcheck
# rim`, 2 ranks), each row's JSON under OUT_DIR (default results/rim-ends)
# with the commands in OUT_DIR/rows.tsv; then scripts/studies/rim_ends_page.py
# writes the page from those files alone, keeping the oblique end's section,
# which scripts/studies/oblique_end.sh writes (517 s on its own).
# Usage: scripts/studies/rim_ends.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/rim-ends}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
# name, the case in words, options: the page's rows in order
rows=(
  "square_sharp|square end (90 deg), sharp, rigid plane, the preprint's load (q = 1e4 N/m, R = 10 mm)|"
  "obtuse_120_sharp|120 deg rim, sharp, rigid plane|--interior-angle 120 --levels 4"
  "obtuse_150_sharp|150 deg rim, sharp, rigid plane|--interior-angle 150 --levels 4"
  "acute_75_sharp|75 deg (acute) rim, sharp, rigid plane|--interior-angle 75 --levels 3")
: > "$out/rows.tsv"
for r in "${rows[@]}"; do
  IFS='|' read -r name what options <<< "$r"
  printf '%s\t%s\t%s\n' "$name" "$what" "mpirun -n 2 rollcheck rim $options" >> "$out/rows.tsv"
  start=$(date +%s)
  # shellcheck disable=SC2086  # the options are words
  mpirun -n 2 --oversubscribe "$bin" -q rim $options --json "$out/$name.json" > "$out/$name.log" 2>&1 \
    || { echo "rim $options failed: see $out/$name.log" >&2; exit 1; }
  echo "$name: $(( $(date +%s) - start )) s" >&2
done
/usr/bin/python3 "$here/scripts/studies/rim_ends_page.py" "$out" "$("$bin" --version | head -1)" \
  "$here/docs/results/rim-ends.md"
