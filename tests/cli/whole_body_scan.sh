#!/usr/bin/env bash
# rollcheck whole-body --scan-directions: the orientations a direction gives
# (no solve): the cylinder's every direction is the same generator under
# uniform line Hertz; the oloid's scan reaches its vertex (180 deg at c =
# 1/4 from the loaded end) and its --direction 67.5 is the nearest-square
# orientation docs/methods/whole-body.md checks; bodies without a ruling exit 2;
# the former --load-rule is refused naming --share-rule.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
"$bin" -q whole-body --body cylinder --scan-directions 90 --json "$tmp/cylinder.json" > "$tmp/cylinder.log" 2>&1 \
  || { echo "FAIL: cylinder scan"; cat "$tmp/cylinder.log"; exit 1; }
# q = F / h = 5000 N/m, b = sqrt(4 q R / (pi E*)), E* = 200 GPa / 0.91: 17.02 um
check_json "cylinder: 4 directions, c = 1/2, square ends, line Hertz's b" \
  '(.orientations | length) == 4 and all(.orientations[]; (.centre_of_pressure - 0.5 | fabs) < 1e-9
   and .interior_angle_deg == [90, 90] and (.end_load_n_per_m[0] - 5000 | fabs) < 1e-6
   and (.end_half_width_m[1] - 1.7019e-5 | fabs) < 1e-8)' "$tmp/cylinder.json"
"$bin" -q whole-body --body oloid --scan-directions 2.5 --json "$tmp/oloid.json" > "$tmp/oloid.log" 2>&1 \
  || { echo "FAIL: oloid scan"; cat "$tmp/oloid.log"; exit 1; }
check_json "oloid: c within [1/4, 3/4], a loaded end at the vertex (180 deg)" \
  'all(.orientations[]; .in_equilibrium and .centre_of_pressure > 0.249 and .centre_of_pressure < 0.751)
   and ([.orientations[] | .interior_angle_deg[1] as $a | select(.end_load_n_per_m[1] > 0) | $a] | max) > 179.9' \
  "$tmp/oloid.json"
expect 2 "sphere not in" -- "$bin" whole-body --body sphere --scan-directions 10 --json "$tmp/sphere.json"
expect 2 "scan_directions_deg" -- "$bin" whole-body --scan-directions -1 --json "$tmp/negative.json"
check '[[ ! -e $tmp/sphere.json && ! -e $tmp/negative.json ]]' "a refused scan left no output"
# --share-rule (how the reduced models share F along the ruling) is not the
# other subcommands' --load-rule (the load each ruling carries): the former
# name is refused naming the new one, as an option and as a case key.
"$bin" -q whole-body --share-rule sections --scan-directions 90 --json "$tmp/share.json" > "$tmp/share.log" 2>&1 \
  || { echo "FAIL: --share-rule sections"; cat "$tmp/share.log"; fail=1; }
expect 2 "load-rule is now --share-rule" -- "$bin" whole-body --load-rule sections --scan-directions 90 \
  --json "$tmp/former.json"
printf '[scene]\nkind = "whole-body"\nload_rule = "sections"\nscan_directions_deg = 90\n' > "$tmp/former.toml"
expect 2 "key 'load_rule' is now 'share_rule'" -- "$bin" run "$tmp/former.toml"
check '[[ ! -e $tmp/former.json ]]' "a refused former option left no output"
exit $fail
