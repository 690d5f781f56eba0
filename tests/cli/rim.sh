#!/usr/bin/env bash
# rollcheck rim and the rim case: a sharp obtuse rim is reported singular
# with its exponent and no end peak; a rounded one with the end/interior
# ratio; the fields are written whole for ParaView; bad input exits 2 naming
# the setting and writes nothing, a PETSc option the solver rejects too.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OPENBLAS_NUM_THREADS=1
"$bin" -q run "$here/cases/rim_obtuse_sharp.toml" --set levels=2 --json "$tmp/sharp.json" > "$tmp/sharp.log" 2>&1 \
  || { echo "FAIL: sharp rim case"; cat "$tmp/sharp.log"; exit 1; }
check '/usr/bin/python3 "$here/postprocess/plot_rim.py" "$tmp/sharp.json" "$tmp/sharp.png" > /dev/null && [[ -s "$tmp/sharp.png" ]]' \
  "the pressure near the rim plots"
check_json "sharp obtuse rim singular, exponent of the wedge, no peak" \
  '.singular == true and .end_to_interior == null and .wedge_exponent < -0.38 and .wedge_exponent > -0.39
   and .measured_exponent < 0 and (.levels | length) == 2 and .counter_face == "rigid"' "$tmp/sharp.json"
"$bin" rim --interior-angle 120 --edge-radius 1.2e-5 --levels 1 --edge-element 0.0625 --xdmf "$tmp/rounded.xdmf" \
  --json "$tmp/rounded.json" > "$tmp/rounded.log" 2>&1 || { echo "FAIL: rounded rim"; cat "$tmp/rounded.log"; exit 1; }
check 'grep -q "^\[info\] rim: level 1 (h_e = [0-9.e-]* m)" "$tmp/rounded.log"' \
  "one end's level is logged as it starts (its progress beat)"
check_json "rounded rim under its boundary layer: not singular, not resolved, so no ratio and no convergence" \
  '.singular == false and .resolved == false and .end_to_interior == null and .end_change == null
   and .converged == false and .boundary_layer_m > 1.8e-8 and .boundary_layer_m < 1.9e-8' "$tmp/rounded.json"
check_json "the centre line reaches 3 b beyond the fillet's start, where its peak lies" \
  '(.levels[0].centre_line_x_m_pressure_pa | map(.[0]) | min) as $x
   | $x < -3 * .half_width_m and $x >= -3 * .half_width_m - .fillet_start_m' "$tmp/rounded.json"
check '/usr/bin/python3 -c "import meshio, sys; m = meshio.read(sys.argv[1]); assert max(m.point_data[\"contact_pressure\"]) > 0" "$tmp/rounded.xdmf"' \
  "the rounded rim's fields read back with a contact pressure"
"$bin" -q rim --counter-face steel --levels 1 --json "$tmp/steel.json" > "$tmp/steel.log" 2>&1 \
  || { echo "FAIL: steel counter-face"; cat "$tmp/steel.log"; exit 1; }
check_json "steel block: the square end singular with the elastic wedge's exponent, b of E* halved" \
  '.counter_face == "steel" and .singular == true and .wedge_exponent < -0.225 and .wedge_exponent > -0.227
   and .half_width_m > 3.40e-5 and .half_width_m < 3.41e-5 and .end_to_interior == null' "$tmp/steel.json"
# The end's direct solver reads the factorisation's options: a value PETSc
# rejects is bad input (exit 2, named), as for any other solver.
"$bin" -q rim --levels 1 --json "$tmp/bad.json" -- -hertz_pc_factor_shift_type bogus > "$tmp/bad.log" 2>&1; rc=$?
check '[[ $rc -eq 2 ]] && grep -q "PETSc rejected" "$tmp/bad.log" && [[ ! -e $tmp/bad.json ]]' \
  "a bad factorisation option: $(tail -n 3 "$tmp/bad.log")"
refuses rim "--interior-angle 180:interior_angle_deg" "--interior-angle 50:interior_angle_deg" \
  "--sheet-radius -1:sheet_radius_m" "--load-per-length nan:load_per_length_n_per_m" "--levels 0:levels" \
  "--xdmf $tmp/f.vtu:--xdmf" "--edge-radius 1e-3:edge_radius_m"
exit $fail
