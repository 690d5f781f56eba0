#!/usr/bin/env bash
# The JSON inputs of the report (`--audit`, `--robustness`, `--validation`) are
# checked before anything is computed: a file that is not the JSON its option
# names exits 2 naming the option and the key it lacks, and `validate` runs
# no case and writes nothing (io/report_json_inputs.h).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
echo '{"not": "robustness"}' > "$tmp/other.json"
echo '[1, 2]' > "$tmp/list.json"
printf '{"comparisons": [' > "$tmp/cut.json"
expect 2 "validate --robustness .*other.json.: no key 'comparisons'" -- \
  "$bin" validate --robustness "$tmp/other.json" --out "$tmp/v1"
check '[[ ! -e $tmp/v1 ]]' "validate wrote its folder before refusing --robustness"
expect 2 "validate --audit .*other.json.: no key 'modes'" -- "$bin" validate --audit "$tmp/other.json" --out "$tmp/v2"
expect 2 "validate --audit .*list.json.: not a JSON object" -- "$bin" validate --audit "$tmp/list.json" --out "$tmp/v3"
expect 2 "validate --robustness .*cut.json.: not a JSON object" -- \
  "$bin" validate --robustness "$tmp/cut.json" --out "$tmp/v4"
expect 2 "--robustness.*directory" -- "$bin" validate --robustness "$tmp" --out "$tmp/v5"
check '[[ ! -e $tmp/v2 && ! -e $tmp/v3 && ! -e $tmp/v4 && ! -e $tmp/v5 ]]' "validate wrote a folder before refusing"
exit $fail
