#!/usr/bin/env bash
# Benchmark (not a test) of the rims' loop against issue 61's budget: the
# rounded oloid over its loop (`rim --body oloid --edge-radius 0.001`, 2
# ranks) in at most 25 times the wall time of `fem-sds --body oloid` (2
# ranks) measured in the same run, with its end-aware status and FEM-SDS.
# Prints both wall times, their ratio, and the loop's status.
#   bash scripts/bench/bench_rim_loop.sh [ROLLCHECK]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
source "$here/scripts/bench/bench_lib.sh"
run fem_sds mpirun -n 2 "$bin" fem-sds --body oloid
run rim_loop mpirun -n 2 "$bin" rim --body oloid --edge-radius 0.001
/usr/bin/python3 - "$tmp" <<'PY'
import json, sys
tmp = sys.argv[1]
fem = float(open(f"{tmp}/fem_sds.s").read())
rim = float(open(f"{tmp}/rim_loop.s").read())
r = json.load(open(f"{tmp}/rim_loop.json"))
aware = r["loop_scores"].get("end_aware") or [{}]
print("| fem-sds s | rim loop s | rim loop / fem-sds (budget 25) | end-aware status | end-aware FEM-SDS |")
print("|---|---|---|---|---|")
print(f"| {fem:.1f} | {rim:.1f} | {rim / fem:.1f} | {r['end_aware_status']} | {aware[0].get('fem_sds', {}).get('value')} |")
PY
