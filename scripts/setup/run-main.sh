#!/usr/bin/env bash
# Quick start 1: install what is missing, build, run the main job
# (`rollcheck audit`, then `rollcheck validate` on the default cases,
# cases/default/, whose report shows the verdicts and the audit table).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bash "$here/scripts/setup/setup.sh"
export OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cd "$here"
mkdir -p results
# The audit of the preprint's claims first, so that the report shows its table
# after the verdicts of the default cases.
mkdir -p results/audit
build/src/cli/rollcheck audit --json results/audit/audit.json --markdown results/audit/audit.md > /dev/null
# The headline comparisons over the modelling choices, whose ranges the report's findings show.
build/src/cli/rollcheck robustness --json results/robustness.json > /dev/null
build/src/cli/rollcheck validate --out results --audit results/audit/audit.json --robustness results/robustness.json \
  --json results/validate.json "$@"
echo "summary: $here/results/validate.json"
