#!/usr/bin/env bash
# rollcheck flat-rim: the half-space model of a rounded, nearly flat rim end
# against the FEM end model (`rollcheck rim`, tests/data/flat_rim) on the
# same end, 170 deg rounded with r_e = 0.4 mm on the rigid plane: the end's
# peak over line Hertz within 5 % of the FEM's end / interior, at the window
# of 100 b and of 200 b (half-space theory's slopes, here tan 10 deg, and the
# two models' far fields, the FEM's block 160 b deep and the window, differ:
# 1.974 and 2.010 against 1.9655 measured); bad input exits 2 naming the
# option (an end of the oloid's loop too steep for half-space theory, a
# body that is no hull of two circles, a whole ruling asked of a straight
# rim as well), before any output.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
"$bin" flat-rim --interior-angle 170 --sheet-radius 1e-3 --load-per-length 1.2e5 --edge-radius 4e-4 \
  --json "$tmp/end.json" > "$tmp/end.log" 2>&1 || { echo "FAIL: flat-rim"; cat "$tmp/end.log"; exit 1; }
fem="$here/tests/data/flat_rim/rim_170deg.json"
check_json "the FEM reference is a converged rounded end" '.converged and (.resolved) and .interior_angle_deg == 170' "$fem"
ratio=$(jq -r '.end_to_interior' "$fem")
check_json "the peak over line Hertz within 5 % of the FEM's ($ratio)" \
  "((.peak_over_line_hertz / $ratio - 1) | fabs) < 0.05" "$tmp/end.json"
check_json "with the window twice as long too" \
  "((.longer_window_peak_pa / .line_hertz_peak_pa / $ratio - 1) | fabs) < 0.05" "$tmp/end.json"
check_json "the peak lies inside the rim line, within the fillet (r_e sin 10 deg)" \
  '.levels[-1].peak_along_m > 0 and .levels[-1].peak_along_m < 4e-4 * 0.17365' "$tmp/end.json"
check_json "far from the end: line Hertz within 1 %" \
  '((.levels[-1].far_peak_pa / .levels[-1].far_line_hertz_pa - 1) | fabs) < 0.01' "$tmp/end.json"
expect 2 "interior-angle" -- "$bin" flat-rim --interior-angle 120 --json "$tmp/steep.json"
expect 2 "edge-radius" -- "$bin" flat-rim --edge-radius -1 --json "$tmp/negative.json"
expect 2 "end-angle" -- "$bin" flat-rim --end-angle 140 --json "$tmp/steep_end.json"
expect 2 "no-such-folder" -- "$bin" flat-rim --json "$tmp/no-such-folder/out.json"
expect 2 "sphere not in" -- "$bin" flat-rim --body sphere --json "$tmp/sphere.json"
expect 2 "square" -- "$bin" flat-rim --body cylinder --json "$tmp/cylinder.json"
expect 2 "whole-ruling" -- "$bin" flat-rim --interior-angle 170 --whole-ruling --json "$tmp/whole_straight.json"
expect 2 "unknown option '--mesh'" -- "$bin" flat-rim --mesh "$here/meshes/reference/oloid_reference.obj" --json "$tmp/mesh.json"
check '[[ ! -e $tmp/steep.json && ! -e $tmp/negative.json && ! -e $tmp/steep_end.json && ! -e $tmp/sphere.json
         && ! -e $tmp/cylinder.json && ! -e $tmp/mesh.json && ! -e $tmp/whole_straight.json ]]' \
  "a refused run left no output"
exit $fail
