#!/usr/bin/env bash
# Benchmark (not a test) of `rollcheck whole-body` (issue 14's fuller check at
# small scale) against its budget of 10 minutes, on 2 ranks: the wall time of
# each check and of its parts (slices, end models, whole body), the whole
# body's DOFs, and the ratio to the budget; beside them the largest
# differences along the ruling and at the ends, against 3 %.
#   bash scripts/bench/bench_whole_body.sh [ROLLCHECK] [-- extra whole-body options]
# (e.g. -- --share-rule coarse-body: the load rule's own time is its column).
# The 10 mm cylinder and the 10 mm oloid at --direction 67.5, its ends
# nearest square (F = 100 N, steel).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=$here/build/src/cli/rollcheck
if [[ $# -gt 0 && $1 != -- ]]; then bin=$1; shift; fi
[[ ${1:-} == -- ]] && shift
source "$here/scripts/bench/bench_lib.sh"
run cylinder mpirun -n 2 "$bin" whole-body --body cylinder --radius 0.01 "$@"
run oloid mpirun -n 2 "$bin" whole-body --body oloid --radius 0.01 --direction 67.5 "$@"
/usr/bin/python3 - "$tmp" <<'PY'
import json, sys
tmp = sys.argv[1]
budget = 600.0
print("| check | load rule | DOFs | node planes x section nodes | rule s | slices s | end models s | whole body s | total s | total / 10 min | worst along | worst end | verdict |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for name in ["cylinder", "oloid"]:
    r = json.load(open(f"{tmp}/{name}.json"))
    total = float(open(f"{tmp}/{name}.s").read())
    w, m = r["wall_s"], r["mesh"]
    compared = [abs(e["difference"]) for e in r["ends"] if e.get("difference") is not None]
    end = f"{100 * max(compared):.2f} %" if compared else "-"
    if r["worst_end"] is None and compared:
        end += " (the compared ends)"
    rule = r.get("coarse_body_share") or r.get("section_share") or {"wall_s": 0.0}
    print(f"| {name} | {r['share_rule']} | {m['dofs']} | {m['node_planes']} x {m['section_nodes']} | {rule['wall_s']:.1f} "
          f"| {w['slices']:.1f} | {w['end_models']:.1f} "
          f"| {w['whole_body']:.1f} | {total:.1f} | {total / budget:.2f} | {100 * r['worst_along']:.2f} % | {end} "
          f"| {r['outcome']} |")
PY
