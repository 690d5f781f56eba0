#!/usr/bin/env bash
# Quick start 2: install what is missing, build, run the whole default test
# suite through CTest (long studies carry the label "long" and are left out;
# run them with `ctest --test-dir build -L long`).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bash "$here/scripts/setup/setup.sh"
export OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ctest --test-dir "$here/build" --output-on-failure -j 2 -LE long "$@"
