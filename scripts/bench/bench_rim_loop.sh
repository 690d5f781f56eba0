#!/usr/bin/env bash
# Benchmark (not a test) of the rims' loop against issue 61's budget: the
# rounded oloid over its loop (`rim --body oloid --edge-radius 0.001`, 2
# ranks) in at most 25 times the wall time of `fem-sds --body oloid` (2
# ranks) measured in the same run, its end-aware status and FEM-SDS, and the
# same loop one level finer (every end model's first edge elements halved,
# --edge-element 0.0625) with the relative difference of its end-aware
# FEM-SDS (the issue asks for at most 0.5 %). Each end model logs its
# levels' wall time and how much of it went to meshing; the loop's log is
# kept as rim_loop.log and rim_loop_finer.log in LOGDIR if given; OPTIONS
# (one quoted string, e.g. "--half-space-ends-from 120") go to both loops.
#   bash scripts/bench/bench_rim_loop.sh [ROLLCHECK [LOGDIR [OPTIONS]]]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
logs=${2:-}
read -r -a options <<< "${3:-}"
source "$here/scripts/bench/bench_lib.sh"
keep_log() { [ -z "$logs" ] || cp "$tmp/log" "$logs/$1.log"; }
run fem_sds mpirun -n 2 "$bin" fem-sds --body oloid
run rim_loop mpirun -n 2 "$bin" rim --body oloid --edge-radius 0.001 "${options[@]}"
keep_log rim_loop
run rim_loop_finer mpirun -n 2 "$bin" rim --body oloid --edge-radius 0.001 --edge-element 0.0625 "${options[@]}"
keep_log rim_loop_finer
/usr/bin/python3 - "$tmp" <<'PY'
import json, sys
tmp = sys.argv[1]
def seconds(name):
    return float(open(f"{tmp}/{name}.s").read())
def aware(name):
    r = json.load(open(f"{tmp}/{name}.json"))
    value = (r["loop_scores"].get("end_aware") or [{}])[0].get("fem_sds", {}).get("value")
    return r["end_aware_status"], value
def end_models(name):  # the end models' wall and meshing seconds, the table's nodes solved and in all
    r = json.load(open(f"{tmp}/{name}.json"))
    models = r["ends"] + [n for n in r["end_table"] if n["reached"]]
    return (sum(m.get("wall_s", 0) for m in models), sum(m.get("mesh_wall_s", 0) for m in models),
            sum(n["reached"] for n in r["end_table"]), len(r["end_table"]), r.get("half_space_ends", 0))
fem, rim, finer = seconds("fem_sds"), seconds("rim_loop"), seconds("rim_loop_finer")
status, sds = aware("rim_loop")
finer_status, finer_sds = aware("rim_loop_finer")
change = f"{100 * (sds / finer_sds - 1):+.2f} %" if sds and finer_sds else "-"
print("| run | wall s | / fem-sds (budget 25) | end-aware status | end-aware FEM-SDS |")
print("|---|---|---|---|---|")
print(f"| fem-sds | {fem:.1f} | 1 | - | - |")
print(f"| rim loop | {rim:.1f} | {rim / fem:.1f} | {status} | {sds} |")
print(f"| rim loop, one level finer | {finer:.1f} | {finer / fem:.1f} | {finer_status} | {finer_sds} |")
print(f"end-aware FEM-SDS at the default over one level finer, less 1: {change}")
for name in ("rim_loop", "rim_loop_finer"):
    wall, mesh, solved, nodes, half_space = end_models(name)
    print(f"{name}: end models {wall:.1f} s, {mesh:.1f} s of it meshing; end table nodes solved {solved} of {nodes}; "
          f"{half_space} end models by half-space theory")
PY
