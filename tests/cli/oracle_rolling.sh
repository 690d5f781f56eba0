#!/usr/bin/env bash
# `rollcheck oracle --oracle rolling`: real rolling of a named body scored with
# the uniformity score U (docs/methods/real-rolling.md).
# - cylinder: only its side is touched, uniformly in time, so its continuum
#   score is U_inf = A / A_side - 1 = (2 pi r h + 2 pi r^2) / (2 pi r h) - 1 = r / h
#   = 1/2 for r = 1, h = 2, at any rolling rate (two energy excesses); the exact
#   body's area comes from a polygon of --mass-points sides, error ~ 1/n^2, so n
#   = 16384 puts it far below 1e-6 (the default 2048 gives 1.2e-6);
# - oloid: holds its ruling for one whole loop; the scoring mesh has the body
#   mesh's faces (as `rollcheck mesh` builds it) times subdivisions^2; the mesh
#   score approaches U_inf from below as the faces are cut finer;
# - the JSON states that cds ... fds are not computed (null);
# - the modelling choices (load rule, contact width, end margin, time law) are
#   inputs: the cylinder's continuum scores stay r / h under them, the oloid's
#   U_inf moves with the load rule, and a uniform rate under the dynamic load
#   (no free motion has one) is refused;
# - a mesh file or a three-circle roller exits 2 with a clear message, nothing written.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
run() { # run NAME ARGS...: the JSON goes to $tmp/NAME.json
  local name=$1; shift
  "$bin" -q oracle --oracle rolling "$@" --json "$tmp/$name.json" 2> "$tmp/$name.err" \
    || { echo "FAIL: oracle --oracle rolling $*"; cat "$tmp/$name.err"; fail=1; }
}

run cylinder --body cylinder --face-subdivisions 2 --mass-points 16384
run cylinder_fast --body cylinder --face-subdivisions 2 --mass-points 16384 --rolling-energy 1
for name in cylinder cylinder_fast; do
  check_json "$name: continuum U = r/h = 0.5" '(.uniformity_score_continuum - 0.5 | fabs) <= 1e-6' "$tmp/$name.json"
  check_json "$name: contact held over one loop" '.contact_held == true and (.loops_completed - 1 | fabs) < 1e-6' "$tmp/$name.json"
done

# The modelling choices as named inputs: the cylinder's every continuum score
# over the whole surface is r / h under any of them; the oloid's U_inf moves
# with the load rule, and the choices are echoed under their names.
run cylinder_static --body cylinder --mass-points 16384 --load-rule static --contact-width geometric --end-margin 0.1
check_json "cylinder, static load, geometric width: every continuum score r/h = 0.5" \
  '([.uniformity_score_continuum, .accumulated_pressure_continuum, .peak_pressure_continuum, .basquin_damage_continuum]
    | all((. - 0.5 | fabs) <= 1e-6)) and (.peak_to_mean_pressure_continuum - 1 | fabs) <= 1e-6
   and .load_rule == "static" and .contact_width == "geometric" and .end_margin == 0.1 and .time_law == "free"' \
  "$tmp/cylinder_static.json"
run oloid_dynamic --body oloid --points 60
run oloid_static --body oloid --points 60 --load-rule static
run oloid_uniform_rate --body oloid --points 60 --load-rule uniform --time-law uniform_rate
jq -n --slurpfile d "$tmp/oloid_dynamic.json" --slurpfile s "$tmp/oloid_static.json" --slurpfile u "$tmp/oloid_uniform_rate.json" \
  '$d[0].load_rule == "dynamic" and $d[0].rolling_energy == 0.1
   and ($d[0].uniformity_score_continuum / $s[0].uniformity_score_continuum - 1 | fabs) > 0.01
   and $u[0].time_law == "uniform_rate" and $u[0].uniformity_score_continuum > 0' > "$tmp/choices.txt"
[[ $(cat "$tmp/choices.txt") == true ]] || { echo "FAIL: the load rule and time law do not reach U_inf"; fail=1; }

run oloid2 --body oloid --points 100 --face-subdivisions 2
run oloid4 --body oloid --points 100 --face-subdivisions 4
"$bin" -q mesh --body oloid --points 100 --json "$tmp/mesh.json" 2> "$tmp/mesh.err" || { echo "FAIL: mesh"; fail=1; }
faces=$(jq -r '.n_faces' "$tmp/mesh.json")
for k in 2 4; do
  j=$tmp/oloid$k.json
  check_json "oloid x$k: every key, the others null and said so" \
    '. as $j | (["uniformity_score","uniformity_score_continuum","coverage","contact_held","loops_completed","initial_rate_rad_s","n_faces","wall_s"] | all(. as $k | $j | has($k)))
     and ([.cds, .sds, .tds, .wds_vol, .wds_depth, .fds] | all(. == null)) and (.not_computed | test("not computed"))' "$j"
  check_json "oloid x$k: n_faces = mesh faces x $k^2" ".n_faces == $faces * $k * $k" "$j"
  check_json "oloid x$k: holds its ruling for one loop" '.contact_held == true and (.loops_completed - 1 | fabs) < 1e-6 and .initial_rate_rad_s > 0' "$j"
  # coverage is a ratio of area sums: 1 up to their round-off (1e-12)
  check_json "oloid x$k: 0 < coverage <= 1, U on the mesh at most U_inf" \
    '.coverage > 0 and .coverage <= 1 + 1e-12 and .uniformity_score > 0 and .uniformity_score <= .uniformity_score_continuum' "$j"
done
jq -n --slurpfile a "$tmp/oloid2.json" --slurpfile b "$tmp/oloid4.json" \
  '$a[0].uniformity_score < $b[0].uniformity_score and $a[0].uniformity_score_continuum == $b[0].uniformity_score_continuum' \
  > "$tmp/converge.txt"
[[ $(cat "$tmp/converge.txt") == true ]] || { echo "FAIL: oloid U should rise towards U_inf as faces are cut finer"; fail=1; }

"$bin" oracle --help > "$tmp/help.txt"
for option in --rolling-energy --loops --face-subdivisions --contact-width --load-rule --end-margin --time-law; do
  grep -A3 -- "$option" "$tmp/help.txt" | grep -q "default" || { echo "FAIL: --help lacks $option with its default"; fail=1; }
done

expect 2 "mesh.*named body" -- "$bin" oracle --oracle rolling --mesh "$source/meshes/reference/oloid_reference.obj" --json "$tmp/bad1.json"
expect 2 "rolling.*3 circles" -- "$bin" oracle --oracle rolling --body roller --circles 3 --theta 120 --json "$tmp/bad2.json"
expect 2 "loops" -- "$bin" oracle --oracle rolling --body oloid --loops 0 --json "$tmp/bad3.json"
expect 2 "uniform_rate" -- "$bin" oracle --oracle rolling --body oloid --time-law uniform_rate --json "$tmp/bad4.json"
expect 2 "load-rule" -- "$bin" oracle --oracle rolling --body oloid --load-rule quasi --json "$tmp/bad5.json"
[[ ! -e $tmp/bad1.json && ! -e $tmp/bad2.json && ! -e $tmp/bad3.json && ! -e $tmp/bad4.json && ! -e $tmp/bad5.json ]] || { echo "FAIL: bad input wrote output"; fail=1; }
exit $fail
