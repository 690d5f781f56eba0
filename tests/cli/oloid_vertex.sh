#!/usr/bin/env bash
# scripts/studies/oloid_vertex.py: the oloid's lower surface near a vertex, found
# from its two circles, against what the geometry says exactly: the ruling
# touches the ground (z = 0 along it), its sheet's radius across grows
# linearly from 0 at P to 2 r1 at its far end (R = 2 x' / sqrt 3), beyond P
# the rim's circle rises as x'^2 / (2 r1), and q(P) = 8 F / (3 L); bad
# input exits non-zero.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
/usr/bin/python3 "$here/scripts/studies/oloid_vertex.py" --radius 0.01 --load 800 > "$tmp/vertex.txt" 2>&1 \
  || { echo "FAIL: oloid_vertex.py"; cat "$tmp/vertex.txt"; exit 1; }
row() { grep -F "| $1 |" "$tmp/vertex.txt" | tr -d ' ' | tr '|' ' '; }
read -r _ z0 _ _ _ radius <<< "$(row +1.0e-03)"
read -r _ beyond _ _ _ _ <<< "$(row -1.0e-03)"
q=$(sed -n 's/.*q(P) = \([0-9.e+-]*\) N\/m.*/\1/p' "$tmp/vertex.txt")
awk -v z0="$z0" -v R="$radius" -v zb="$beyond" -v q="$q" 'BEGIN {
  L = sqrt(3) * 0.01
  bad = (z0 < -1e-15 || z0 > 1e-15) || ((R / (2e-3 / sqrt(3))) - 1 > 0.01 || (R / (2e-3 / sqrt(3))) - 1 < -0.01) \
        || ((zb / (1e-6 / 0.02)) - 1 > 0.01 || (zb / (1e-6 / 0.02)) - 1 < -0.01) \
        || ((q / (8 * 800 / (3 * L))) - 1 > 1e-4 || (q / (8 * 800 / (3 * L))) - 1 < -1e-4)
  exit bad }' || { echo "FAIL: z0 $z0, R $radius, beyond $beyond, q $q against the exact geometry"; cat "$tmp/vertex.txt"; fail=1; }
/usr/bin/python3 "$here/scripts/studies/oloid_vertex.py" --radius -1 > "$tmp/bad.txt" 2>&1 && { echo "FAIL: a negative radius passed"; fail=1; }
grep -q -- "--radius" "$tmp/bad.txt" || { echo "FAIL: the refusal does not name --radius"; cat "$tmp/bad.txt"; fail=1; }
exit ${fail:-0}
