#!/usr/bin/env bash
# scripts/studies/rounded_end_half_space.py: its half-space solver (Love's
# rectangles on a graded grid, mirror images, the active-set contact) against
# Hertz's sphere, p0 within 0.5 % and the contact's radius within 1 %; bad
# input exits 2 naming the option.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OPENBLAS_NUM_THREADS=1
script="$here/scripts/studies/rounded_end_half_space.py"
/usr/bin/python3 "$script" --check > "$tmp/check.txt" 2>&1 || { echo "FAIL: the Hertz check"; cat "$tmp/check.txt"; fail=1; }
grep -q "^Hertz sphere" "$tmp/check.txt" || { echo "FAIL: no check line"; cat "$tmp/check.txt"; fail=1; }
/usr/bin/python3 "$script" --rho -1 > "$tmp/bad.txt" 2>&1
[[ $? == 2 ]] || { echo "FAIL: a negative R / r_e did not exit 2"; fail=1; }
grep -q -- "--rho" "$tmp/bad.txt" || { echo "FAIL: the refusal does not name --rho"; cat "$tmp/bad.txt"; fail=1; }
exit ${fail:-0}
