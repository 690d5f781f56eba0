#!/usr/bin/env bash
# The rims' oblique end of docs/results/rim-ends.md: the oloid loop's most
# oblique rim end solved with its edge crossing the ruling at the real angle
# and by the perpendicular reduction at its dihedral angle
# (`rollcheck rim --body oloid --oblique-study`, two ranks), sharp (q = 1e4
# N/m, R = 10 mm) and rounded at the rounded rims' settings (r1 = 10 mm,
# F = 800 N through the centre of mass, r_e = 0.4 mm: the end's own q and R
# in that loop, as scripts/studies/rim_load_rules.sh's loop takes them),
# then the page's section between its markers
# (scripts/studies/oblique_end_page.py). WHICH (both, sharp or rounded)
# runs one part alone, the page keeping the other as it stands.
# Usage: scripts/studies/oblique_end.sh [ROLLCHECK_BINARY] [OUT_DIR] [LEVELS] [WHICH]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
out=${2:-$here/results/oblique_end}
mkdir -p "$out"
bin=${1:-$here/build/src/cli/rollcheck}
levels=${3:-2}
which=${4:-both}
rounded="rim --body oloid --radius 0.01 --load 800 --oblique-study --oblique-loop-load --edge-radius 4e-4 --levels $levels"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
run() { # NAME ARGS...: one study, its JSON in OUT_DIR/NAME.json
  local name=$1 start
  shift
  start=$(date +%s)
  mpirun -n 2 --oversubscribe "$bin" "$@" --json "$out/$name.json" > "$out/$name.log" 2>&1 \
    || { echo "the oblique end ($name) failed: see $out/$name.log" >&2; exit 1; }
  echo "oblique study, $name: $(( $(date +%s) - start )) s" >&2
}
sharp_json=- rounded_json=-
case $which in
  both|sharp) run oblique rim --body oloid --oblique-study --levels "$levels"; sharp_json=$out/oblique.json ;;&
  both|rounded)
    # shellcheck disable=SC2086  # the command's words
    run rounded $rounded; rounded_json=$out/rounded.json ;;
  sharp) ;;
  *) echo "WHICH must be both, sharp or rounded, got '$which'" >&2; exit 2 ;;
esac
/usr/bin/python3 "$here/scripts/studies/oblique_end_page.py" "$sharp_json" "$rounded_json" \
  "$("$bin" --version | head -1)" "$here/docs/results/rim-ends.md" "mpirun -n 2 rollcheck $rounded"
