#!/usr/bin/env bash
# Regenerates docs/results/real-rolling.md: real rolling scored with U
# (`rollcheck oracle --oracle rolling`), one JSON per body, rolling energy
# and contact width under OUT_DIR (default results/real-rolling); then
# scripts/studies/real_rolling_page.py writes the page from those files alone.
# Usage: scripts/studies/real_rolling.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/real-rolling}
mkdir -p "$out"
# name: body options (the preprint's candidates as two-circle rollers)
declare -A bodies=(
  [oloid]="--body oloid" [cylinder]="--body cylinder" [paper-oloid]="--body paper-oloid"
  [c120_130_080]="--body roller --theta 120 --offset 1.30 --ratio 0.80"
  [c90_070_080]="--body roller --theta 90 --offset 0.70 --ratio 0.80"
  [c120_070_080]="--body roller --theta 120 --offset 0.70 --ratio 0.80")
# runs: body, rolling energy, contact width (every table's rows; the page reads them by these names)
runs=(
  "oloid 0.02 hertz" "oloid 0.1 hertz" "oloid 0.36 hertz" "oloid 0.5 hertz" "oloid 1 hertz" "oloid 3 hertz"
  "cylinder 0.1 hertz" "cylinder 3 hertz" "oloid 0.1 geometric"
  "paper-oloid 0.02 hertz" "paper-oloid 0.1 hertz" "paper-oloid 0.5 hertz" "paper-oloid 1 hertz" "paper-oloid 3 hertz"
  "c120_130_080 0.02 hertz" "c120_130_080 0.1 hertz" "c120_130_080 0.5 hertz" "c120_130_080 1 hertz"
  "c120_130_080 3 hertz" "c90_070_080 0.1 hertz" "c120_070_080 0.1 hertz")
for r in "${runs[@]}"; do
  read -r name energy width <<< "$r"
  # shellcheck disable=SC2086  # the body options are words
  "$bin" -q oracle --oracle rolling ${bodies[$name]} --rolling-energy "$energy" --contact-width "$width" \
    --json "$out/${name}_${energy}_${width}.json" > /dev/null
done
/usr/bin/python3 "$here/scripts/studies/real_rolling_page.py" "$out" "$("$bin" --version | head -1)" \
  > "$here/docs/results/real-rolling.md"
