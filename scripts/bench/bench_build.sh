#!/usr/bin/env bash
# Benchmark (not a test) of a clean build: the tree as it is, configured
# into two new build folders without ccache, once without the precompiled
# headers (-DROLLCHECK_PCH=OFF, the build as it was before them) and once
# with them (-DROLLCHECK_PCH=ON), one after the other in the same run; prints both
# wall times and their ratio (the goal: at most 0.5), and the slowest
# translation units of each build from ninja's log.
#   bash scripts/bench/bench_build.sh [JOBS [TARGET...]]
#   OBJECTS=REGEX bash scripts/bench/bench_build.sh [JOBS]
# JOBS defaults to 2 (the CI machine's cores); TARGETs default to everything.
# OBJECTS builds the object files whose path matches REGEX, e.g.
# 'rollcheck_fem.dir/scenes/', with what they need first: the precompiled
# headers they use and, through CMake's order-only dependencies, the
# libraries their target links (a part of the build, not one folder alone).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
jobs=${1:-2}
shift || true
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
export CCACHE_DISABLE=1
build() { # NAME PCH: configure and build into $tmp/NAME, its wall seconds in $tmp/NAME.s
  local name=$1 pch=$2 start end
  cmake -S "$here" -B "$tmp/$name" -G Ninja -DCMAKE_BUILD_TYPE=Release -DROLLCHECK_PCH="$pch" > /dev/null
  local targets=("$@")
  if [ -n "${OBJECTS:-}" ]; then
    mapfile -t targets < <(ninja -C "$tmp/$name" -t targets all | cut -d: -f1 | grep -E '\.o$' | grep -E "$OBJECTS")
  fi
  start=$(date +%s.%N)
  ninja -C "$tmp/$name" -j "$jobs" "${targets[@]}" > "$tmp/$name.log" 2>&1 || { tail -30 "$tmp/$name.log"; exit 1; }
  end=$(date +%s.%N)
  echo "$end - $start" | bc -l > "$tmp/$name.s"
}
build without OFF "$@"
build with ON "$@"
# -Winvalid-pch (set by CMake) reports a header the compiler refused to use.
refused=$(grep -c "not using\|not used because" "$tmp/with.log" || true)
/usr/bin/python3 - "$tmp" "$jobs" "${OBJECTS:+objects matching $OBJECTS}${*}" "$refused" <<'PY'
import sys
tmp, jobs, targets, refused = sys.argv[1], sys.argv[2], sys.argv[3] or "everything", sys.argv[4]
def slowest(name, n=5):
    rows = []
    for line in open(f"{tmp}/{name}/.ninja_log"):
        if line.startswith("#"):
            continue
        start, end, _, out, _ = line.rstrip("\n").split("\t")
        rows.append(((int(end) - int(start)) / 1000, out))
    rows.sort(reverse=True)
    return len(rows), rows[:n]
without, with_pch = (float(open(f"{tmp}/{n}.s").read()) for n in ("without", "with"))
print(f"clean build of {targets}, -j {jobs}, no ccache")
print(f"  without precompiled headers: {without:.0f} s")
print(f"  with precompiled headers:    {with_pch:.0f} s")
print(f"  ratio with / without: {with_pch / without:.2f} (goal <= 0.50); precompiled headers refused: {refused}")
for name in ("without", "with"):
    steps, top = slowest(name)
    print(f"  {name}: {steps} steps; slowest: " + ", ".join(f"{out.split('/')[-1]} {s:.0f} s" for s, out in top))
PY
