#!/usr/bin/env bash
# Benchmark (not a test) of issue 61: the 3D hemisphere's default against
# the axisymmetric default, both on 2 ranks in the same run. Prints each
# run's DOFs, wall time (the process's, start to end, and the solver's
# wall_s), its two pointwise errors against Hertz (largest nodal pressure,
# profile RMS / p0) and the 3D / axi wall ratios; the goal is both errors
# within 0.5 % at most 12x the axisymmetric wall time.
#   bash scripts/bench/bench_hertz3d.sh [ROLLCHECK] [REPEATS]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
repeats=${2:-3}
source "$here/scripts/bench/bench_lib.sh"
for ((i = 1; i <= repeats; ++i)); do
  run "axi$i" mpirun -n 2 "$bin" hertz --model axi
  run "3d$i" mpirun -n 2 "$bin" hertz --model 3d
done
/usr/bin/python3 - "$tmp" "$repeats" <<'PY'
import json, statistics, sys
tmp, repeats = sys.argv[1], int(sys.argv[2])
rows = {}
print("| run | recovery | DOFs | process s (median) | wall_s (median) | nodal p max err % | profile RMS % | RMS r < 0.9 a % |")
print("|---|---|---|---|---|---|---|---|")
for model in ["axi", "3d"]:
    runs = [json.load(open(f"{tmp}/{model}{i}.json")) for i in range(1, repeats + 1)]
    process = statistics.median(float(open(f"{tmp}/{model}{i}.s").read()) for i in range(1, repeats + 1))
    wall = statistics.median(r["wall_s"] for r in runs)
    r = runs[0]
    rows[model] = (process, wall)
    print(f"| {model} | {r['pressure_recovery']} | {r['dofs']} | {process:.2f} | {wall:.2f} | "
          f"{100 * r['p_max_nodal_error']:+.3f} | {100 * r['profile_rms_error']:.3f} | "
          f"{100 * r['profile_rms_error_interior']:.3f} |")
print(f"3d / axi: process {rows['3d'][0] / rows['axi'][0]:.2f}x, wall_s {rows['3d'][1] / rows['axi'][1]:.2f}x "
      f"(goal: at most 12x, both errors within 0.5 %)")
PY
