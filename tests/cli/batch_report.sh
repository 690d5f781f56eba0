#!/usr/bin/env bash
# `rollcheck report --from STORE` and `rollcheck validate`: the Markdown and
# HTML report of a store of mesh cases (tables; each plot it has no data for
# is named with what it needs), replaced whole on a re-run; bad input exits 2
# and writes nothing; validate runs a folder of cases as a batch and prints
# where its report is.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/cases"
# Each case states a check, as validate requires (the cylinder r = 1, h = 2:
# area 2 pi r h + 2 pi r^2 of the inscribed 60-gon prism, within 0.5 %).
printf '[scene]\nkind = "mesh"\nbody = "oloid"\npoints = 100\n[[check]]\npointer = "/area_m2"\nvalue = 12.566370614359172\nrel_tol = 0.005\nreference = "4 pi r^2"\n' > "$tmp/cases/oloid.toml"
printf '[scene]\nkind = "mesh"\nbody = "cylinder"\n[[check]]\npointer = "/area_m2"\nvalue = 18.84955592153876\nrel_tol = 0.005\nreference = "6 pi r^2"\n' > "$tmp/cases/cylinder.toml"
batch_ok batch "$tmp/cases" --out "$tmp/out"

"$bin" report --from "$tmp/out/results.h5" > "$tmp/report.out" 2>&1
check '[[ $? -eq 0 ]]' "report: exit code"
check 'grep -q "report: $tmp/out/report/report.html" "$tmp/report.out"' "report: path not printed"
md=$tmp/out/report/report.md
check '[[ -s $md && -s $tmp/out/report/report.html ]]' "report files"
check 'grep -q "^| oloid | mesh | ok |" "$md"' "cases table"
check 'grep -q "^### Scene .mesh.: 2 cases$" "$md"' "results table"
check '[[ $(grep -c "This plot is not drawn" "$md") -eq 5 ]]' "the five plots are not all named as not drawn"
check 'grep -q "</html>" "$tmp/out/report/report.html"' "html"
"$bin" report --from "$tmp/out/results.h5" > /dev/null 2>&1
check '! ls -A "$tmp/out" | grep -q "^\.report"' "a re-run left temporary report folders"

"$bin" report --from "$tmp/none.h5" > "$tmp/missing.out" 2>&1
check '[[ $? -eq 2 ]] && grep -q "none.h5" "$tmp/missing.out"' "missing store: not an input error"
"$bin" report --from "$tmp/out/results.h5" --out "$tmp/r2" --python "$tmp/nopython" > "$tmp/nopy.out" 2>&1
check '[[ $? -eq 2 ]] && grep -q "nopython" "$tmp/nopy.out" && [[ ! -e $tmp/r2 ]]' "missing python: not an input error, or output written"

"$bin" validate --cases "$tmp/cases" --out "$tmp/validate" --json "$tmp/validate.json" > "$tmp/validate.out" 2>&1
check '[[ $? -eq 0 ]]' "validate: exit code"
check 'grep -q "report: $tmp/validate/report/report.html" "$tmp/validate.out"' "validate: report path not printed"
check '[[ -s $tmp/validate/report/report.md && -s $tmp/validate/results.h5 ]]' "validate: store and report"
check 'grep -q "\"computed\": 2" "$tmp/validate.json"' "validate: JSON summary"
exit $fail
