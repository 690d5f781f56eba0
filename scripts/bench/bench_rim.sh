#!/usr/bin/env bash
# Benchmark (not a test) of `rollcheck rim` against issue 14's budget of 60 s
# for one end solved at converged accuracy: the wall time of each study, the
# time of its last (finest) level, and the ratio to the budget.
#  - square end, rigid plane, 3 levels (2 ranks);
#  - 120 deg sharp rim, rigid plane, 4 levels (2 ranks): the exponent's fit;
#  - 120 deg rim rounded (2 b), 2.0 GPa, 4 levels (2 ranks): resolved;
#  - square end on the steel block, 4 levels (2 ranks);
#  - the rounded 120 deg rim on the steel block, 4 levels (2 ranks).
#   bash scripts/bench/bench_rim.sh [ROLLCHECK]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
source "$here/scripts/bench/bench_lib.sh"
run square mpirun -n 2 "$bin" rim
run sharp120 mpirun -n 2 "$bin" run "$here/cases/rim_obtuse_sharp.toml"
run rounded120 mpirun -n 2 "$bin" run "$here/cases/rim_obtuse_rounded.toml"
run steel mpirun -n 2 "$bin" rim --counter-face steel --levels 4
run rounded120steel mpirun -n 2 "$bin" run "$here/cases/rim_steel_rounded.toml"
/usr/bin/python3 - "$tmp" <<'PY'
import json, sys
tmp = sys.argv[1]
budget = 60.0
print("| study | verdict | levels | study s | finest level s | finest / 60 s budget |")
print("|---|---|---|---|---|---|")
for name in ["square", "sharp120", "rounded120", "steel", "rounded120steel"]:
    r = json.load(open(f"{tmp}/{name}.json"))
    total = float(open(f"{tmp}/{name}.s").read())
    finest = r["levels"][-1]["wall_s"]
    print(f"| {name} | {r['verdict']} | {len(r['levels'])} | {total:.1f} | {finest:.1f} | {finest / budget:.2f} |")
PY
