#!/usr/bin/env bash
# One output convention (docs/guide/command-line.md#conventions): a
# subcommand's result summary goes to stdout, its log to stderr; -q and -v
# are accepted before or after the subcommand; `--json -` keeps stdout JSON
# alone; a misspelt option gets the closest option's name; only the FEM
# subcommands' help mentions PETSc; no subcommand's help offers a choice it
# always refuses.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"

# -q before and after the subcommand: the result on stdout, nothing on stderr.
for line in "-q oracle --body oloid" "oracle --body oloid -q"; do
  # shellcheck disable=SC2086
  "$bin" $line > "$tmp/out" 2> "$tmp/err"; rc=$?
  check '[[ $rc -eq 0 ]]' "rollcheck $line: exit $rc ($(head -c 500 "$tmp/err"))"
  check 'grep -q "^| CDS | [0-9.e+-]* |" "$tmp/out"' "rollcheck $line: no CDS row on stdout ($(head -c 500 "$tmp/out"))"
  check '[[ ! -s $tmp/err ]]' "rollcheck $line: -q left log lines on stderr ($(head -c 300 "$tmp/err"))"
done
# -v after the subcommand: debug lines on stderr, the table still on stdout.
"$bin" oracle --body oloid --oracle approx -v > "$tmp/out" 2> "$tmp/err"
check 'grep -q "^\[debug\]" "$tmp/err"' "-v after the subcommand: no debug line on stderr"
check 'grep -q "^| CDS |" "$tmp/out" && ! grep -q "^\[" "$tmp/out"' "-v: the table is not alone on stdout"

# The summaries of mesh and hertz are tables on stdout; the logs stay on stderr.
"$bin" mesh --body cylinder > "$tmp/out" 2> /dev/null
check 'grep -q "^| cylinder | faces |" "$tmp/out"' "mesh: no summary table on stdout ($(cat "$tmp/out"))"
"$bin" hertz --model axi --refine 0 > "$tmp/out" 2> "$tmp/err"
check 'grep -q "^| p0 (Hertz-form fit) \[Pa\] |" "$tmp/out" && grep -q "^| largest nodal pressure \[Pa\] |" "$tmp/out"' \
  "hertz: no table of the fitted p0 and the largest nodal pressure on stdout ($(cat "$tmp/out"))"
check '! grep -q "^|" "$tmp/err"' "hertz: the table went to stderr"

# --json -: stdout is the JSON alone, the table goes to the log.
"$bin" oracle --body oloid --oracle approx --json - > "$tmp/out.json" 2> "$tmp/err"
check 'jq -e ".cds > 0" "$tmp/out.json" > /dev/null' "--json -: stdout is not JSON alone ($(head -c 300 "$tmp/out.json"))"
check 'grep -q "| CDS |" "$tmp/err"' "--json -: the table is not in the log"

# Misspelt options: the closest option is named; an unknown one points to --help.
expect 2 "unknown option '--raduis' \(did you mean '--radius'\?\)" -- "$bin" hertz --raduis 0.01
expect 2 "unknown option '--bodyy' \(did you mean '--body'\?\)" -- "$bin" oracle --bodyy oloid
expect 2 "unknown option '--zzzzzz'; .rollcheck mesh --help. lists" -- "$bin" mesh --zzzzzz
expect 2 "unknown option '--quite' \(did you mean '--quiet'\?\)" -- "$bin" --quite mesh
# Two edits that change most of a short name are no typo: no suggestion.
expect 2 "unknown option '--nu'; " -- "$bin" hertz --nu 0.3

# The PETSc footer only in the help of FEM subcommands.
for sub in mesh oracle search optimize report audit robustness; do
  check '! "$bin" $sub --help 2>&1 | grep -q PETSc' "$sub --help mentions PETSc"
done
for sub in hertz fem-sds rim; do
  check '"$bin" $sub --help 2>&1 | grep -q "PETSc options follow"' "$sub --help lacks the PETSc footer"
done

# No choice in help that the subcommand refuses: the line-contact scenes take
# no mesh file, no sphere and no circle count.
for sub in fem-sds rim flat-rim whole-body; do
  "$bin" $sub --help > "$tmp/help" 2>&1
  check '! grep -qE -- "--mesh |--circles |--subdivisions |uv-sphere|hemisphere" "$tmp/help"' \
    "$sub --help offers a body it refuses: $(grep -E -- "--mesh |--circles |uv-sphere" "$tmp/help" | head -3)"
done
exit $fail
