#!/usr/bin/env bash
# rollcheck crease and the crease case: apex pressure growing level by level,
# p(a/2) within 2 % of the blunt-wedge solution; bad input exits 2 naming it.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OPENBLAS_NUM_THREADS=1
here=$(cd "$(dirname "$0")/../.." && pwd)
"$bin" -q run "$here/cases/crease_kink.toml" --set levels=3 --json "$tmp/crease.json" > "$tmp/crease.log" 2>&1 \
  || { echo "FAIL: crease case"; cat "$tmp/crease.log"; exit 1; }
/usr/bin/python3 - "$tmp/crease.json" <<'PY' || fail=1
import json, math, sys
r = json.load(open(sys.argv[1]))
E_star = 200e9 / (1 - 0.3**2)
coefficient = E_star * math.tan(math.radians(5)) / math.pi
assert abs(r["half_width_m"] / (1e4 / (E_star * math.tan(math.radians(5)))) - 1) < 1e-12
assert abs(r["half_contact_pressure_pa"] / (coefficient * math.acosh(2)) - 1) < 1e-12
apex = [l["apex_pressure_pa"] for l in r["levels"]]
assert len(apex) == 3 and all(b > a for a, b in zip(apex, apex[1:])), apex
for l in r["levels"]:
    assert abs(l["half_contact_pressure_pa"] / r["half_contact_pressure_pa"] - 1) < 0.02, l
assert r["apex_pressure_converged"] is False
print("apex", apex, "Pa: grows; p(a/2) converged")
PY
for args in "--face-angle 50:face_angle_deg" "--load-per-length -1:load_per_length_n_per_m" "--refine -5:refine" "--levels 1:levels" "--width nan:width_m"; do
  "$bin" -q crease ${args%%:*} > "$tmp/bad.log" 2>&1; rc=$?
  if [[ $rc -ne 2 ]] || ! grep -q -- "${args#*:}" "$tmp/bad.log"; then
    echo "FAIL: crease ${args%%:*} gave exit $rc without '${args#*:}':"; cat "$tmp/bad.log"; fail=1
  fi
done
exit $fail
