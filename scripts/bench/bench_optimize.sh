#!/usr/bin/env bash
# Benchmark (not a test) of rollcheck optimize on 2 threads. Two tables:
#
# 1. A local search for the CDS of the preprint's roller family (approximate
#    oracle, paper-compatible, BOBYQA from (90, 1, 1) in the default box) at a
#    few mesh resolutions: per resolution the distinct genomes scored, the
#    oracle runs, the wall time and the time per run.
# 2. Issue 17's budgets for the fast scores: a local search within 5 minutes
#    and a global one within 30. Per score (CDS and SDS under the approximate
#    and the rigid-body oracle, paper-compatible, 300 points per circle; U of
#    real rolling, centre-line family, 100 points per circle), with and
#    without matched face count: a local search (BOBYQA, at most 400
#    evaluations; it usually stops by itself) and a global one (DIRECT-L,
#    1000 evaluations), each timed as the whole command (noise replicates,
#    search, derivatives at the start and at the optimum, sweeps). Rigid
#    scores average 16 replicates, the costlier choice docs/methods/optimize.md
#    recommends. FEM-SDS is not a fast score (rollcheck-fem under mpirun).
#
# Both tables use the JSON's wall_s; the search itself is sequential, and the
# two threads share the noise replicates, the rigid replicates, the
# derivatives' stencils and the sweeps.
#   bash scripts/bench/bench_optimize.sh [path/to/rollcheck] [max evaluations of table 1]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
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

echo
printf "| score | matching | search | evaluations | genomes scored | oracle runs | wall s | budget s | within |\n"
printf "|---|---|---|---|---|---|---|---|---|\n"
scores=("cds --oracle approx --paper-compat --points 300"
        "sds --oracle approx --paper-compat --points 300"
        "cds --oracle rigid --paper-compat --points 300 --replicates 16"
        "sds --oracle rigid --paper-compat --points 300 --replicates 16"
        "uniformity --oracle rolling --family centre-line --points 100")
searches=("local:--method bobyqa --max-evaluations 400:300" "global:--method direct-l --max-evaluations 1000:1800")
for score in "${scores[@]}"; do
  for matching in "" --matched-resolution; do
    for search in "${searches[@]}"; do
      IFS=: read -r kind options limit <<< "$search"
      # shellcheck disable=SC2086 # the options are words
      "$bin" -q optimize --score $score $matching $options --threads 2 --json "$tmp/r.json"
      /usr/bin/python3 - "$tmp/r.json" "$score" "${matching:+faces}" "$kind" "$limit" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))
score, matching, kind, limit = sys.argv[2], sys.argv[3] or "points", sys.argv[4], float(sys.argv[5])
s = r["search"]
print(f"| `{score}` | {matching} | {kind} ({s['method']}) | {s['evaluations']} | {r['score_evaluations']} | "
      f"{r['oracle_runs']} | {r['wall_s']:.1f} | {limit:.0f} | {'yes' if r['wall_s'] <= limit else 'NO'} |")
PY
    done
  done
done
