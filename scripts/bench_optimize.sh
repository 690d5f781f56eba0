#!/usr/bin/env bash
# Benchmark (not a test): a local search for the CDS of the preprint's roller
# family (approximate oracle, paper-compatible, BOBYQA from (90, 1, 1) in the
# default box) at a few mesh resolutions; prints per resolution the distinct
# genomes scored, the oracle runs, the wall time and the time per run. Two
# threads share the noise replicates, the derivatives' stencils and the sweeps;
# the search itself is sequential.
#   bash scripts/bench_optimize.sh [path/to/rollcheck] [max evaluations]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
budget=${2:-100}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export OPENBLAS_NUM_THREADS=1
printf "| points per circle | max evaluations | genomes scored | oracle runs | wall s | ms per run |\n|---|---|---|---|---|---|\n"
for points in 100 200 300; do
  "$bin" -q optimize --score cds --oracle approx --paper-compat --family paper --points "$points" \
    --max-evaluations "$budget" --threads 2 --json "$tmp/r.json"
  /usr/bin/python3 - "$tmp/r.json" "$points" "$budget" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
print(f"| {sys.argv[2]} | {sys.argv[3]} | {r['score_evaluations']} | {r['oracle_runs']} | {r['wall_s']:.2f} | "
      f"{1000 * r['wall_s'] / r['oracle_runs']:.1f} |")
PY
done
