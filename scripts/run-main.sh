#!/usr/bin/env bash
# Quick start 1: install what is missing, build, run the main job
# (`rollcheck validate` on the embedded default cases, cases/default/).
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bash "$here/scripts/setup.sh"
export OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
mkdir -p results
build/src/cli/rollcheck validate --out results --json results/validate.json "$@"
echo "summary: $here/results/validate.json"
