#!/usr/bin/env bash
# The content of the report (postprocess/make_report.py, docs/guide/report.md) of a
# small store (a mesh case and the axisymmetric Hertz case): the verdicts come
# first after the findings, a failed validation check is marked failed, the numbers in a caption
# are the store's, a single refine level is said not to be a curve, a missing
# optional input says how to get it, and a key missing from a plot's input or
# from the validation file is an error naming it. Needs python3-jinja2.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
python=/usr/bin/python3
rm -rf "$tmp"; mkdir -p "$tmp/cases"
printf '[scene]\nkind = "mesh"\nbody = "oloid"\npoints = 100\n' > "$tmp/cases/oloid.toml"
cp "$source/cases/default/hertz_axisymmetric.toml" "$tmp/cases/hertz_axi.toml"
batch_ok batch "$tmp/cases" --out "$tmp/out" || exit 1
store=$tmp/out/results.h5
cat > "$tmp/validation.json" << 'EOF'
{"checks": [
  {"case": "oloid", "kind": "mesh", "pointer": "/area_m2", "criterion": "within 1 % of 12.566", "measured": "12.5",
   "reference": "oloid area 4 pi r^2", "passed": true},
  {"case": "hertz_axi", "kind": "hertz", "pointer": "/p0_error", "criterion": "|x| <= 1e-09", "measured": "0.001",
   "reference": "Hertz: p0 = 3F / (2 pi a^2)", "passed": false}],
 "passed": 1, "failed": 1}
EOF
report() { "$python" "$source/postprocess/make_report.py" --store "$1" --out "$2" "${@:3}"; }

report "$store" "$tmp/r" --validation "$tmp/validation.json" > "$tmp/r.out" 2>&1
check '[[ $? -eq 0 ]]' "report with --validation: exit code ($(tail -3 "$tmp/r.out"))"
md=$tmp/r/report.md; html=$tmp/r/report.html
check '[[ $(grep "^## " "$md" | head -2 | tr "\n" /) == "## 1. Findings/## 2. Verdicts/" ]]' \
  "Markdown: the findings and the verdicts are not the first two sections"
line() { grep -n -m1 -e "$1" "$2" | cut -d: -f1; }
check '(( $(line "^| result | case |" "$md") < $(line "^## 3\." "$md") ))' \
  "Markdown: the check table is not in section 2"
check 'grep -q "^\*\*2 checks: 1 passed, 1 failed\.\*\*" "$md"' "Markdown: check counts"
check '(( $(line "^| FAIL | hertz_axi | hertz | /p0_error |" "$md") < $(line "^| PASS | oloid |" "$md") ))' \
  "Markdown: the failed check is not marked FAIL and listed first"
pos() { grep -b -o -m1 -e "$1" "$2" | head -1 | cut -d: -f1; }
check '(( $(pos "<table class=\"checks\">" "$html") < $(pos "<section id=\"audit\">" "$html") ))' \
  "HTML: the check table is not before the audit"
check '(( $(pos "<table class=\"checks\">" "$html") < $(pos "<section id=\"plots\">" "$html") ))' \
  "HTML: the check table is not before the plots"
check 'grep -q "<tr class=\"fail\"><td>FAIL</td><td>hertz_axi</td>" "$html"' \
  "HTML: the failed check is not marked fail"
check '! grep -q "src=.[a-z_]*\.png" "$html"' "HTML: an image is not embedded"
check 'grep -q "No audit was given. Run .rollcheck audit --json" "$md"' "missing --audit: not said how to get it"
# The caption's numbers are the store's: p0_error as the conclusion prints it.
p0=$("$python" -c "import h5py, sys
print(f'{100 * abs(h5py.File(sys.argv[1])[\"cases/hertz_axi/summary/p0_error\"][()]):.2g} %')" "$store")
check 'grep -q "hertz_axi: FEM peak pressure within $p0 " "$md"' \
  "profile caption does not state the store's p0 error ($p0)"
check 'grep -q "axi P1: a single refine level" "$md"' "speed-error caption does not say it has a single point"

report "$store" "$tmp/none" > /dev/null 2>&1
check 'grep -q "No validation checks were given. .rollcheck validate." "$tmp/none/report.md"' \
  "missing --validation: not said how to get it"

# A key missing from a plot's input: an error naming the key and the case, no report.
cp "$store" "$tmp/broken.h5"
"$python" -c "import h5py, sys
del h5py.File(sys.argv[1], 'r+')['cases/hertz_axi/summary/p0_hertz_pa']" "$tmp/broken.h5"
report "$tmp/broken.h5" "$tmp/b" > "$tmp/b.out" 2>&1
check '[[ $? -ne 0 ]]' "missing plot key: exit code 0"
check 'grep -q "case hertz_axi (hertz summary): no key .p0_hertz_pa." "$tmp/b.out"' \
  "missing plot key: not named"
check '[[ ! -e $tmp/b/report.html ]]' "missing plot key: a report was written"
# A key missing from the validation file: an error naming it.
sed 's/"measured": "0.001",//' "$tmp/validation.json" > "$tmp/no_measured.json"
report "$store" "$tmp/v" --validation "$tmp/no_measured.json" > "$tmp/v.out" 2>&1
check '[[ $? -ne 0 ]] && grep -q "checks/1: no key .measured." "$tmp/v.out"' \
  "missing validation key: not named"
exit $fail
