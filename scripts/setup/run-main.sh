#!/usr/bin/env bash
# Quick start 1: install what is missing, build, run the main job
# (`rollcheck audit --quick`, then `rollcheck validate` on the default cases,
# cases/default/, whose report shows the verdicts and the audit table).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bash "$here/scripts/setup/setup.sh" rollcheck rollcheck-fem
export OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# The FEM slice table's nodes, solved once for the whole job: the audit's
# commands and the default cases build the same table (docs/guide/command-line.md).
ROLLCHECK_SLICE_TABLE_DIR=$(mktemp -d)
export ROLLCHECK_SLICE_TABLE_DIR
trap 'rm -rf "$ROLLCHECK_SLICE_TABLE_DIR"' EXIT
cd "$here"
mkdir -p results
# The audit of the preprint's claims first (its quick mode: the full audit,
# `bash scripts/studies/audit.sh`, takes minutes), so that the report shows
# its table after the verdicts of the default cases. Its commands' outputs are
# kept: the report's ranges over the modelling choices and its fatigue-life
# section are those of its `rollcheck robustness` and `rollcheck life`
# commands, not computed a second time.
# The default cases run beside it (their verdicts wait for `validate`, which
# finds them done): the two share the cores and the slice table.
mkdir -p results/audit
build/src/cli/rollcheck batch cases/default --out results &
cases=$!
build/src/cli/rollcheck audit --quick --json results/audit/audit.json --markdown results/audit/audit.md \
  --outputs results/audit/commands > /dev/null
wait "$cases" || true # a failed case is run again, and reported, by validate
kept() { jq -r --arg c "rollcheck $1 " '[.commands[] | select(.command | startswith($c))][0].id' results/audit/audit.json; }
build/src/cli/rollcheck validate --out results --audit results/audit/audit.json \
  --robustness "results/audit/commands/$(kept robustness).json" --life "results/audit/commands/$(kept life).json" \
  --json results/validate.json "$@"
echo "summary: $here/results/validate.json"
