#!/usr/bin/env bash
# Benchmark (not a test): `rollcheck rounded-end` (C++, the rounded end by
# half-space theory on a graded grid) against the numpy prototype it
# replaced (scripts/studies/rounded_end_half_space.py, one BLAS thread
# both), one level each on the same grid, at rows R / r_e and held length
# L / b given as "RHO:L" arguments (default: the rim loop's 120 deg row at
# r_e = 20 b, 10:210, and the rounded oloid's first end, 531:621). Prints
# each row's cells, both wall times, their ratio and the two end / interior
# ratios' relative difference (the prototype is the reference).
#   bash scripts/bench/bench_rounded_end.sh [ROLLCHECK] [RHO:L ...]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
shift $(($# < 1 ? $# : 1))
rows=("$@")
((${#rows[@]})) || rows=(10:210 531:621)
source "$here/scripts/bench/bench_lib.sh"
echo "| R / r_e | L / b | cells | rollcheck s | numpy s | numpy / rollcheck | end / interior | vs numpy |"
echo "|---|---|---|---|---|---|---|---|"
for row in "${rows[@]}"; do
  rho=${row%%:*}; length=${row##*:}
  # R = rho r_e with r_e = 1 mm; q sets b so that L / b is the row's with --depth.
  radius=$(echo "$rho * 0.001" | bc -l)
  run "c$rho" "$bin" rounded-end --sheet-radius "$radius" --load-per-length 1e3 --edge-radius 0.001 \
    --depth "$length" --levels 1
  start=$(date +%s.%N)
  /usr/bin/python3 "$here/scripts/studies/rounded_end_half_space.py" --rho "$rho" --length "$length" > "$tmp/p$rho.txt"
  end=$(date +%s.%N); numpy_s=$(echo "$end - $start" | bc -l)
  /usr/bin/python3 - "$tmp/c$rho.json" "$(cat "$tmp/c$rho.s")" "$numpy_s" "$(tail -1 "$tmp/p$rho.txt")" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
ours, numpy = float(sys.argv[2]), float(sys.argv[3])
cells = sys.argv[4].split("|")
level = r["levels"][0]
reference = float(cells[5])
print(f"| {r['sheet_over_edge_radius']:g} | {r['held_length_over_half_width']:g} | {level['cells']} (numpy {cells[3].strip()}) "
      f"| {ours:.1f} | {numpy:.1f} | {numpy / ours:.1f}x | {level['end_to_interior']:.4f} | "
      f"{100 * (level['end_to_interior'] / reference - 1):+.4f} % |")
PY
done
