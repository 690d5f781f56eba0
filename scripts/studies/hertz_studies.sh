#!/usr/bin/env bash
# Reproduces the Hertz FEM studies of the README ("Hertz FEM"): the penalty
# study (penalty_c 0.1..1000 on each model's default mesh), the
# convergence study (refine levels of every model and degree) and the
# pointwise study (3D cost against the pointwise errors, lumped and
# consistent pressure recovery), each a CSV, a PNG and the runs' JSON under
# OUT (default results/hertz). Runs on RANKS MPI ranks (default 1,
# so that the wall times of all models compare; the 2D models use MUMPS, 3D
# GMRES + GAMG). About 5 minutes on an idle 2-core machine.
#   scripts/studies/hertz_studies.sh [OUT] [RANKS]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
out=${1:-$here/results/hertz}
ranks=${2:-1}
bin=${ROLLCHECK:-$here/build/src/cli/rollcheck}
[[ -x $bin ]] || { echo "no rollcheck at $bin (build first, or set ROLLCHECK)" >&2; exit 2; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
run=("$bin")
((ranks > 1)) && run=(mpirun -n "$ranks" "$bin")
mkdir -p "$out"
"${run[@]}" hertz --study penalty --out "$out" --json "$out/hertz_penalty.json"
"${run[@]}" hertz --study convergence --out "$out" --json "$out/hertz_convergence.json"
"${run[@]}" hertz --study pointwise --out "$out" --json "$out/hertz_pointwise.json"
echo "written: $out/hertz_penalty.{csv,png} $out/hertz_convergence.{csv,png} $out/hertz_pointwise.{csv,png}"
