#!/usr/bin/env bash
# The defaults' runs of docs/results/hertz.md: each model's default, the 3D
# one on 2 ranks and serial, and the 3D one with two other materials, each
# JSON as OUT_DIR/default_NAME.json with the commands in OUT_DIR/defaults.tsv
# (read by scripts/studies/hertz_page.py).
# Usage: scripts/studies/hertz_defaults.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/hertz}
mkdir -p "$out"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
# name, ranks, options: the defaults' table, in its order
defaults=(
  "axi 1 --model axi"
  "plane_strain 1 --model plane-strain"
  "3d 2 --model 3d"
  "3d_serial 1 --model 3d"
  "3d_aluminium 2 --model 3d --radius 0.025 --youngs-modulus 70e9 --poisson 0.33 --load 2000"
  "3d_glass 2 --model 3d --radius 0.002 --youngs-modulus 63e9 --poisson 0.22 --load 0.5")
: > "$out/defaults.tsv"
for d in "${defaults[@]}"; do
  read -r name ranks options <<< "$d"
  run=("$bin") shown="rollcheck hertz $options"
  ((ranks > 1)) && run=(mpirun -n "$ranks" --oversubscribe "$bin") shown="mpirun -n $ranks $shown"
  printf '%s\t%s\n' "$name" "$shown" >> "$out/defaults.tsv"
  # shellcheck disable=SC2086  # the options are words
  "${run[@]}" -q hertz $options --json "$out/default_$name.json" > /dev/null
done
