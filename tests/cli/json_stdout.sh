#!/usr/bin/env bash
# `--json -` means stdout is exactly one JSON document (the result table and
# the logs go to stderr), for every subcommand that takes --json: each is run
# in a small configuration and its stdout parsed by `python3 -m json.tool`.
# A subcommand whose help offers --json and that has no line here fails the
# test, so a new one cannot slip past. Five take a minute or more even when small and
# are left out: audit (its claim table goes to stdout only when --json is not
# '-', src/cli/audit.cpp), robustness, life, flat-rim and rim (their tables go
# through print_summary, cli/json_option.cpp, as every other's; measured
# under `--json -`: JSON alone on stdout).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; src=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/cases" "$tmp/checked"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
cd "$tmp" || exit 1
printf '[scene]\nkind = "mesh"\nbody = "sphere"\nsubdivisions = 1\n' > cases/sphere.toml
cp "$src/cases/default/geometry_oloids.toml" checked/ # validate: a case with its checks
# report reads a store; the subcommands run in --help's order, report before batch.
batch_ok "the batch for report's store" cases --out prepared -j 1
declare -A line=(
  [mesh]="mesh --body cylinder"
  [oracle]="oracle --body oloid --oracle approx --points 50 --steps 50"
  [run]="run cases/sphere.toml"
  [batch]="batch cases --out batch -j 1"
  [validate]="validate --cases checked --out validate"
  [report]="report --from prepared/results.h5 --out report"
  [search]="search --grid quick --points 50 --anchor-points 50 --steps 50 --rows 3"
  [whole-body]="whole-body --scan-directions 30"
  [hertz]="hertz --model axi --refine 0"
  [crease]="crease --levels 2"
  [optimize]="optimize --max-evaluations 3 --points 50 --steps 50 --sweep-points 2"
  [rounded-end]="rounded-end --sheet-radius 0.004 --load-per-length 1e4 --depth 20 --finest 0.5 --across 0.25"
  [fem-sds]="fem-sds --body cylinder --samples-per-loop 256 --orientations 1 --fem-slices 2 --slab-check 0"
)
skipped=(audit robustness life flat-rim rim)
for sub in $("$bin" --help | sed -n '/^Subcommands:/,$p' | awk 'NR > 1 && /^  [a-z]/ {print $1}'); do
  "$bin" "$sub" --help 2>&1 | grep -q -- "--json" || continue
  [[ " ${skipped[*]} " == *" $sub "* ]] && continue
  if [[ -z ${line[$sub]:-} ]]; then
    echo "FAIL: $sub takes --json but has no command line in this test"; fail=1; continue
  fi
  # shellcheck disable=SC2086
  "$bin" ${line[$sub]} --json - > "$tmp/$sub.out" 2> "$tmp/$sub.err"; rc=$?
  check '[[ $rc -eq 0 ]]' "rollcheck ${line[$sub]} --json -: exit $rc ($(tail -c 500 "$tmp/$sub.err"))"
  check 'python3 -m json.tool "$tmp/$sub.out" > /dev/null 2>&1' \
    "rollcheck ${line[$sub]} --json -: stdout is not one JSON document ($(head -c 300 "$tmp/$sub.out"))"
done
exit $fail
