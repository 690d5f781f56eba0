#!/usr/bin/env bash
# Benchmark (not a test) of `rollcheck flat-rim` against issue 14's budget of
# 60 s for one end solved at converged accuracy (one process): the finished
# oloid's vertex on the rigid plane and on steel, and rim's 170 deg rounded
# end; the wall time (both levels and the doubled window), the finest
# level's, the ratio to the budget, and the peak's changes.
#   bash scripts/bench/bench_flat_rim.sh [ROLLCHECK]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
source "$here/scripts/bench/bench_lib.sh"
run vertex_rigid "$bin" flat-rim
run vertex_steel "$bin" flat-rim --counter-face steel
run straight_170 "$bin" flat-rim --interior-angle 170 --sheet-radius 1e-3 --load-per-length 1.2e5 --edge-radius 4e-4
/usr/bin/python3 - "$tmp" <<'PY'
import json, sys
tmp = sys.argv[1]
print("| study | peak (Pa) | cells halved | window doubled | converged | study s | finest level s | study / 60 s budget |")
print("|---|---|---|---|---|---|---|---|")
for name in ["vertex_rigid", "vertex_steel", "straight_170"]:
    r = json.load(open(f"{tmp}/{name}.json"))
    total = float(open(f"{tmp}/{name}.s").read())
    print(f"| {name} | {r['peak_pressure_pa']:.4g} | {100 * r['last_change']:+.2f} % | {100 * r['window_change']:+.2f} % | "
          f"{r['converged']} | {total:.1f} | {r['levels'][-1]['wall_s']:.1f} | {total / 60:.2f} |")
PY
