#!/usr/bin/env bash
# Benchmark (not a test) of issue 61: the 3D hemisphere's default (P2 on the
# cap's rings) and the 3D P1 model (--degree 1) against the axisymmetric
# default, all on 2 ranks in the same run, and any 3D setups given as extra
# arguments (each one quoted string of options, e.g.
# "--degree 2 --refine 0 --pole-refine 2 --edge-refine 2 --pressure-recovery
# touching"; PETSc options after a `--` in it, "... -- -hertz_ksp_rtol 1e-8"). Prints each run's DOFs, wall time (the process's, start to
# end, and the solver's wall_s), CPU time (user + system of mpirun and its
# ranks: less disturbed by other jobs on a shared machine), its pointwise
# errors against Hertz (largest nodal pressure, profile RMS / p0 over
# s < 1.5 a and over s < 0.9 a, the fitted p0), its ratios to the
# axisymmetric default and whether it meets the goal: both pointwise errors
# within 0.5 % at most 12x the axisymmetric process time.
#   bash scripts/bench/bench_hertz3d.sh [ROLLCHECK] [REPEATS] ["3D OPTIONS" ...]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
repeats=${2:-3}
shift $(($# < 2 ? $# : 2))
setups=("--model axi" "--model 3d" "--model 3d --degree 1")
for extra in "$@"; do setups+=("--model 3d $extra"); done
source "$here/scripts/bench/bench_lib.sh"
printf '%s\n' "${setups[@]}" > "$tmp/setups"
for ((i = 1; i <= repeats; ++i)); do
  for k in "${!setups[@]}"; do
    read -r -a options <<< "${setups[$k]}"
    run "s${k}_$i" /usr/bin/time -f "%U %S" -o "$tmp/s${k}_$i.cpu" mpirun -n 2 "$bin" hertz "${options[@]}"
  done
done
/usr/bin/python3 - "$tmp" "$repeats" <<'PY'
import json, statistics, sys
tmp, repeats = sys.argv[1], int(sys.argv[2])
setups = open(f"{tmp}/setups").read().splitlines()
print("| setup | DOFs | process s (median) | wall_s (median) | CPU s (median) | process / axi | wall_s / axi "
      "| CPU / axi | nodal p max err % | profile RMS % | RMS s < 0.9 a % | p0 (fit) err % | goal |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
axi = None
for k, setup in enumerate(setups):
    tries = range(1, repeats + 1)
    runs = [json.load(open(f"{tmp}/s{k}_{i}.json")) for i in tries]
    process = statistics.median(float(open(f"{tmp}/s{k}_{i}.s").read()) for i in tries)
    cpu = statistics.median(sum(map(float, open(f"{tmp}/s{k}_{i}.cpu").read().split()[-2:])) for i in tries)
    wall = statistics.median(r["wall_s"] for r in runs)
    axi = axi or (process, wall, cpu)
    r = runs[0]
    nodal, rms = r["p_max_nodal_error"], r["profile_rms_error"]
    goal = "-" if k == 0 else ("met" if process <= 12 * axi[0] and abs(nodal) <= 0.005 and rms <= 0.005
                               else "not met")
    print(f"| `{setup}` | {r['dofs']} | {process:.2f} | {wall:.2f} | {cpu:.2f} | {process / axi[0]:.2f}x | "
          f"{wall / axi[1]:.2f}x | {cpu / axi[2]:.2f}x | {100 * nodal:+.3f} | {100 * rms:.3f} | "
          f"{100 * r['profile_rms_error_interior']:.3f} | {100 * r['p0_error']:+.3f} | {goal} |")
print("goal: 3d within 12x the axi process time, nodal p max and profile RMS within 0.5 %")
PY
