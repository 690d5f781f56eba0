#!/usr/bin/env bash
# The report concludes (docs/guide/report.md): its first section,
# <section id="findings">, comes before any table and holds the headline
# figure, drawn from the robustness study's JSON (`rollcheck robustness
# --json`, read, not rerun). Its fatigue-life section, <section id="life">,
# holds the life study's figure and its comparisons as the JSON has them
# (`rollcheck life --json`, a coarse run). Rendered in headless Chromium at 1280x800, the
# first screen shows the findings' paragraph and the top of the headline
# figure; the test skips that part, saying so, where no browser is installed
# (Debian's chromium, scripts/setup/setup.sh).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; source=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/cases"
printf '[scene]\nkind = "mesh"\nbody = "oloid"\npoints = 100\n' > "$tmp/cases/oloid.toml"
batch_ok batch "$tmp/cases" --out "$tmp/out" || exit 1
"$bin" -q robustness --samples-per-loop 200 --pieces 4 --family-samples-per-loop 200 --json "$tmp/robustness.json" > /dev/null \
  || { echo "FAIL: robustness"; exit 1; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
"$bin" -q life --samples-per-loop 400 --pieces 4 --refines 2 --edge-radii 0.01 0.04 --json "$tmp/life.json" > /dev/null \
  || { echo "FAIL: life"; exit 1; }
expect 0 "report: " -- "$bin" report --from "$tmp/out/results.h5" --out "$tmp/report" --robustness "$tmp/robustness.json" \
  --life "$tmp/life.json"
html=$tmp/report/report.html
pos() { grep -b -o -m1 -e "$1" "$html" | head -1 | cut -d: -f1; }
check '[[ -n $(pos "<section id=\"findings\">") ]]' "no findings section"
check '(( $(pos "<section id=\"findings\">") < $(pos "<table") ))' "the findings section is not before every table"
findings=$(sed -n '/<section id="findings">/,/<\/section>/p' "$html")
check 'grep -q "<img src=\"data:image/png;base64," <<<"$findings"' "the findings section holds no image"
check 'grep -q "cylinder / oloid ratio of contact-time uniformity spans" <<<"$findings"' \
  "the findings paragraph does not state the real-rolling range"
# The range stated is the JSON's, turned into cylinder / oloid.
range=$(/usr/bin/python3 -c "import json, sys
c = next(c for c in json.load(open(sys.argv[1]))['comparisons'] if c['score'] == 'contact_time_u' and c['bodies'] == ['oloid', 'cylinder'])
print(f\"{1 / c['ratio_max']:.3g}-{1 / c['ratio_min']:.3g}x\")" "$tmp/robustness.json")
check 'grep -q "spans $range over the modelling choices" <<<"$findings"' "the paragraph's range is not the JSON's ($range)"
check '! grep -q "\.report\.tmp" "$tmp/report/report.log"' "report.log names the temporary folder it was drawn in"
life=$(sed -n '/<section id="life">/,/<\/section>/p' "$html")
check 'grep -q "<figure id=\"life-figure\">" <<<"$life" && grep -q "<img src=\"data:image/png;base64," <<<"$life"' \
  "the fatigue-life section holds no figure"
check '[[ -s $tmp/report/life.png ]] && grep -q "](life.png)" "$tmp/report/report.md"' "no life.png beside report.md"
# The oloid's range in the section is the JSON's.
read -r lo hi <<<"$(/usr/bin/python3 -c "import json, sys
c = next(c for c in json.load(open(sys.argv[1]))['comparisons'] if c['name'] == 'oloid vs cylinder' and c['model'] == 'lundberg_palmgren' and c['criterion'] == 'orthogonal_shear')
print(f\"{c['life_ratio_min']:.3g} {c['life_ratio_max']:.3g}\")" "$tmp/life.json")"
check 'grep -qF ">$lo</td><td class=\"n\">$hi<" <<<"$life"' "the section's oloid vs cylinder range is not the JSON's ($lo, $hi)"
check 'grep -q "neither body.*reaches its fatigue limit" <<<"$life"' "the section does not say why Ioannides-Harris cannot be tested"

browser=$(command -v chromium || command -v chromium-browser || true)
if [[ -z $browser ]]; then
  echo "SKIP: no chromium installed (apt-get install chromium): the first screen was not rendered"
  exit $fail
fi
shoot() { timeout 120 "$browser" --headless --no-sandbox --disable-gpu --hide-scrollbars --window-size=1280,800 "$@" 2>/dev/null; }
shoot --screenshot="$tmp/first_screen.png" "file://$html" > /dev/null
check '[[ -s $tmp/first_screen.png ]]' "no screenshot"
/usr/bin/python3 -c "import sys, matplotlib.image as im
shot = im.imread(sys.argv[1])
sys.exit(0 if shot.shape[:2] == (800, 1280) and shot.std() > 0.02 else 1)" "$tmp/first_screen.png" \
  || { echo "FAIL: the screenshot is not a 1280x800 page with content"; fail=1; }
# Where the browser lays out the paragraph and the figure, measured in the page at that size.
sed 's|</body>|<script>const p = document.querySelector("#findings p.lead").getBoundingClientRect(), f = document.querySelector("#findings img").getBoundingClientRect(); document.body.dataset.layout = [p.top, p.bottom, f.top, f.bottom].join(" ");</script></body>|' \
  "$html" > "$tmp/report/probe.html"
read -r p_top p_bottom f_top f_bottom <<<"$(shoot --dump-dom "file://$tmp/report/probe.html" | grep -o 'data-layout="[^"]*"' | cut -d'"' -f2)"
check '[[ -n ${f_top:-} ]] && (( ${p_bottom%.*} < 800 && ${f_top%.*} < 800 ))' \
  "at 1280x800 the paragraph or the headline figure starts below the first screen (paragraph ${p_top:-?}-${p_bottom:-?}, figure ${f_top:-?}-${f_bottom:-?})"
exit $fail
