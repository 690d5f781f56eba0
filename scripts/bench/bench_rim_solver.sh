#!/usr/bin/env bash
# Benchmark (not a test): the rim end's linear solver on gmsh's tetrahedra.
# One level of three ends on the rigid plane, one process each, with the
# default (MUMPS LU up to RimEndSettings::direct_solver_max_dofs) and
# with the 3D iterative default forced (-hertz_ksp_type gmres -hertz_pc_type
# gamg): unknowns, wall seconds, peak memory, the ratios, and the end/far
# pressure ratio of both (the same problem, so it agrees to the solvers'
# tolerance).
#   bash scripts/bench/bench_rim_solver.sh [BUILD_CLI_FOLDER]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cli=${1:-$here/build/src/cli}
export OPENBLAS_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
declare -A ends=(
  [square]="--interior-angle 90 --edge-element 0.125"
  [acute]="--interior-angle 60 --load-per-length 571769.86 --edge-radius 9.1e-4 --depth 52 --edge-element 0.03125"
  [obtuse]="--interior-angle 120 --sheet-radius 0.01 --load-per-length 172600 --edge-radius 1e-3 --depth 105 --edge-element 0.0625"
)
# solve NAME SOLVER ARGS...: "dofs wall MB end/far" of one level into $tmp/NAME.SOLVER.
solve() {
  local name=$1 solver=$2; shift 2
  local petsc=()
  [[ $solver == gamg ]] && petsc=(-- -hertz_ksp_type gmres -hertz_pc_type gamg)
  /usr/bin/time -f "%e %M" -o "$tmp/time" "$cli/rollcheck-fem" -q rim "$@" --levels 1 --json "$tmp/$name.json" \
    "${petsc[@]}" > /dev/null 2> "$tmp/log" || { cat "$tmp/log"; exit 1; }
  /usr/bin/python3 - "$tmp/$name.json" "$tmp/time" > "$tmp/$name.$solver" <<'PY'
import json, sys
level = json.load(open(sys.argv[1]))["levels"][0]
wall, kb = open(sys.argv[2]).read().split()
print(level["dofs"], wall, int(kb) / 1024, level["end_peak_pa"] / level["far_peak_pa"])
PY
}
printf '%-7s %8s %9s %9s %7s %8s %8s %7s %12s\n' end DOFs "LU s" "GAMG s" "GAMG/LU" "LU MB" "GAMG MB" "LU/GAMG" "ratio change"
for name in square acute obtuse; do
  read -ra args <<< "${ends[$name]}"
  solve "$name" lu "${args[@]}"
  solve "$name" gamg "${args[@]}"
  read -r dofs lu_s lu_mb lu_ratio < "$tmp/$name.lu"
  read -r _ gamg_s gamg_mb gamg_ratio < "$tmp/$name.gamg"
  printf '%-7s %8d %9.1f %9.1f %6.2fx %8.0f %8.0f %6.2fx %12.1e\n' "$name" "$dofs" "$lu_s" "$gamg_s" \
    "$(echo "$gamg_s / $lu_s" | bc -l)" "$lu_mb" "$gamg_mb" "$(echo "$lu_mb / $gamg_mb" | bc -l)" \
    "$(echo "($gamg_ratio - $lu_ratio) / $lu_ratio" | bc -l)"
done
