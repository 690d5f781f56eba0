#!/usr/bin/env bash
# `rollcheck validate` validates: a case whose result breaks its stated
# tolerance makes it exit 1, with the failed check in the verdict table, in
# validation.json and first in the report; the same case with its own
# tolerance passes (exit 0). A case stating no check fails too.
#   validate_checks.sh ROLLCHECK SOURCE_DIR TMP_DIR
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/strict" "$tmp/stated" "$tmp/unchecked"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
cp "$source/cases/default/hertz_axisymmetric.toml" "$tmp/stated/"
# The same case with p0 required within 1e-9 of Hertz: the FEM's 0.09 % breaks it.
sed 's/^max_abs = 0.003$/max_abs = 1e-9/' "$source/cases/default/hertz_axisymmetric.toml" > "$tmp/strict/hertz_axisymmetric.toml"
printf '[scene]\nkind = "mesh"\nbody = "oloid"\n' > "$tmp/unchecked/oloid.toml"

"$bin" validate --cases "$tmp/stated" --out "$tmp/out_stated" > "$tmp/stated.log" 2>&1
check '[[ $? -eq 0 ]] && grep -q "3 checks passed, 0 failed" "$tmp/stated.log"' "the stated tolerances did not pass"

"$bin" validate --cases "$tmp/strict" --out "$tmp/out_strict" > "$tmp/strict.log" 2>&1
rc=$?
check '[[ $rc -eq 1 ]]' "a broken tolerance gave exit $rc"
check 'grep -qE "/a_error .*\*\*FAIL\*\*" "$tmp/strict.log"' "the verdict table does not mark the failed check"
check '/usr/bin/python3 -c "import json,sys; v=json.load(open(sys.argv[1])); assert v[\"failed\"] == 2 and v[\"passed\"] == 1, v" "$tmp/out_strict/validation.json"' "validation.json does not count 2 failed, 1 passed"
check 'grep -q "FAIL" "$tmp/out_strict/report/report.md"' "the report does not show the failed check"

"$bin" validate --cases "$tmp/unchecked" --out "$tmp/out_unchecked" > "$tmp/unchecked.log" 2>&1
rc=$?
check '[[ $rc -eq 1 ]] && grep -q "states no \[\[check\]\]" "$tmp/unchecked.log"' "a case without checks was not a failure (exit $rc)"
[[ $fail -ne 0 ]] && tail -20 "$tmp"/*.log
exit $fail
