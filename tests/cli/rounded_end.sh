#!/usr/bin/env bash
# rollcheck rounded-end: rim's rounded end by half-space theory on a graded
# grid against an independent computation, the numpy prototype
# scripts/studies/rounded_end_half_space.py, on the same grids (R / r_e = 4,
# held over 40 b, two levels): the same cells and end / interior within
# 1e-4 at each level, converged; against the fuller model, the FEM end
# model at 120 deg, r_e = 20 b, R / r_e = 10, held as deep as its block
# (tests/data/rounded_end), within 2 % (measured +1.45 % at cells of s / 4
# and s / 8, +1.47 % at the default s / 8 and s / 16; the FEM's own last
# level +0.53 %); a contact that outgrows the grid across (R / r_e = 100,
# held over 3504 b: it widens near the fillet's start) is solved on a wider
# grid, within 1 % of a grid coarser across that holds it; the scene's JSON
# and summary; bad input exits 2 naming the option before any output (a
# fillet below 2 b, a hold below 10 b, above 5000 b or within 4 boundary
# layers of the fillet, levels whose dense matrices would not fit, a
# missing folder).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OPENBLAS_NUM_THREADS=1
"$bin" rounded-end --sheet-radius 0.004 --load-per-length 1e4 --edge-radius 0.001 --depth 40 --finest 0.25 \
  --across 0.125 --json "$tmp/end.json" > "$tmp/end.log" 2>&1 || { echo "FAIL: rounded-end"; cat "$tmp/end.log"; exit 1; }
script="$here/scripts/studies/rounded_end_half_space.py"
for level in 0 1; do
  finest=$(jq -r ".levels[$level].finest_cell_over_layer" "$tmp/end.json")
  row=$(/usr/bin/python3 "$script" --rho 4 --length 40 --finest "$finest" --across 0.125 | tail -1)
  cells=$(echo "$row" | awk -F'|' '{print $4}'); ratio=$(echo "$row" | awk -F'|' '{print $6}')
  check_json "level $level: the prototype's $cells cells and end / interior $ratio" \
    ".levels[$level].cells == ($cells) and ((.levels[$level].end_to_interior / ($ratio) - 1) | fabs) < 1e-4" "$tmp/end.json"
done
check_json "converged over two levels, R / r_e = 4, r_e / b above 2" \
  '.converged and (.levels | length) == 2 and .sheet_over_edge_radius == 4 and .edge_radius_over_half_width > 2' \
  "$tmp/end.json"
check_json "the peak is end / interior times the far side, over line Hertz's p0" \
  '((.peak_pressure_pa / (.levels[-1].peak_over_p0 * .line_hertz_peak_pa) - 1) | fabs) < 1e-12' "$tmp/end.json"
fem="$here/tests/data/rounded_end/rim_120deg.json"
check_json "the FEM reference is a converged, resolved rounded end" '.converged and .resolved and .edge_radius_m == 0.001' "$fem"
ratio=$(jq -r '.end_to_interior' "$fem")
"$bin" rounded-end --sheet-radius 0.01 --load-per-length 43156.6 --edge-radius 1e-3 --depth 210 --finest 0.25 \
  --json "$tmp/fem_check.json" > "$tmp/fem_check.log" 2>&1 || { echo "FAIL: rounded-end at the FEM's end"; cat "$tmp/fem_check.log"; exit 1; }
check_json "converged, within 2 % above the FEM's $ratio" \
  ".converged and .end_to_interior / $ratio - 1 > 0 and .end_to_interior / $ratio - 1 < 0.02" "$tmp/fem_check.json"
wide="--sheet-radius 0.1 --load-per-length 15.5 --edge-radius 1e-3 --levels 1 --finest 0.5"
# shellcheck disable=SC2086
"$bin" rounded-end $wide --across 0.0625 --json "$tmp/widened.json" > "$tmp/widened.log" 2>&1 \
  || { echo "FAIL: rounded-end on a contact wider than its grid"; cat "$tmp/widened.log"; fail=1; }
# shellcheck disable=SC2086
"$bin" rounded-end $wide --across 0.125 --json "$tmp/coarse_across.json" > "$tmp/coarse_across.log" 2>&1 \
  || { echo "FAIL: rounded-end, coarser across"; cat "$tmp/coarse_across.log"; fail=1; }
coarse=$(jq -r '.end_to_interior' "$tmp/coarse_across.json")
check_json "widened across once (1.75 b to 2.625 b), within 1 % of the coarser grid's $coarse" \
  ".levels[0].extent_over_half_width == 2.625 and ((.end_to_interior / $coarse - 1) | fabs) < 0.01" "$tmp/widened.json"
grep -q "end / interior .*converged" "$tmp/end.log" || { echo "FAIL: no verdict in the summary"; cat "$tmp/end.log"; fail=1; }
expect 2 "edge-radius" -- "$bin" rounded-end --edge-radius 1e-6 --json "$tmp/small.json"
expect 2 "depth" -- "$bin" rounded-end --depth 5 --json "$tmp/short.json"
expect 2 "levels" -- "$bin" rounded-end --levels 4 --finest 0.01 --json "$tmp/huge.json"
expect 2 "block-depth 10.5 r_e = 4.362e" -- "$bin" rounded-end --load-per-length 1e-20 --json "$tmp/long.json"
expect 2 "block-depth 1 r_e" -- "$bin" rounded-end --sheet-radius 0.004 --load-per-length 1e4 --edge-radius 3.5e-5 \
  --block-depth 1 --json "$tmp/short_block.json"
expect 2 "depth 20) lies within 4" -- "$bin" rounded-end --sheet-radius 0.004 --load-per-length 1e4 --edge-radius 1 \
  --depth 20 --json "$tmp/layer.json"
expect 2 "no-such-folder" -- "$bin" rounded-end --json "$tmp/no-such-folder/out.json"
check '[[ ! -e $tmp/small.json && ! -e $tmp/short.json && ! -e $tmp/huge.json && ! -e $tmp/long.json
         && ! -e $tmp/short_block.json && ! -e $tmp/layer.json ]]' "a refused run left no output"
exit $fail
