#!/usr/bin/env bash
# Benchmark (not a test) of a clean build: the tree as it is against a base
# commit (BASE, default 691141b: the last commit before the unity batches
# and the tests' precompiled headers), checked out with `git worktree add`
# into a temporary folder. Both are configured with their defaults into new
# build folders and built one after the other in the same run, without
# ccache, with the same -j. Prints for each the wall time, the processor time
# of the whole build (user + system, of ninja and every compiler and linker
# it started: what the machine's load moves least), the sum of ninja's step
# times from .ninja_log, its steps and its slowest steps; and the ratios new /
# base (the goal: at most 0.5).
#   bash scripts/bench/bench_build.sh [JOBS [TARGET...]]
#   BASE=COMMIT bash scripts/bench/bench_build.sh [JOBS [TARGET...]]
# JOBS defaults to 2 (the CI machine's cores); TARGETs default to everything
# (give targets both trees have, e.g. rollcheck rollcheck-fem).
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
jobs=${1:-2}
shift || true
base=${BASE:-691141b}
tmp=$(mktemp -d)
cleanup() {
  git -C "$here" worktree remove --force "$tmp/base-src" 2> /dev/null || true
  rm -rf "$tmp"
}
trap cleanup EXIT
git -C "$here" worktree add --detach "$tmp/base-src" "$base" > /dev/null 2>&1
export CCACHE_DISABLE=1
build() { # NAME SOURCE [TARGET...]: configure SOURCE into $tmp/NAME and build it
  local name=$1 source=$2
  shift 2
  cmake -S "$source" -B "$tmp/$name" -G Ninja -DCMAKE_BUILD_TYPE=Release > /dev/null
  # RUSAGE_CHILDREN of the python process holds ninja's and, since each
  # process waits for its own, every compiler's and linker's times.
  /usr/bin/python3 - "$tmp/$name" "$jobs" "$@" > "$tmp/$name.times" 2> "$tmp/$name.log" <<'PY' ||
import resource, subprocess, sys, time
folder, jobs, targets = sys.argv[1], sys.argv[2], sys.argv[3:]
start = time.monotonic()
status = subprocess.run(["ninja", "-C", folder, "-j", jobs, *targets], stdout=sys.stderr).returncode
wall = time.monotonic() - start
usage = resource.getrusage(resource.RUSAGE_CHILDREN)
print(wall, usage.ru_utime + usage.ru_stime)
sys.exit(status)
PY
    { tail -30 "$tmp/$name.log"; exit 1; }
}
build base "$tmp/base-src" "$@"
build new "$here" "$@"
# -Winvalid-pch (set by CMake) reports a precompiled header the compiler refused.
refused=$(grep -c "not using\|not used because" "$tmp/new.log" || true)
/usr/bin/python3 - "$tmp" "$jobs" "$base" "${*:-everything}" "$refused" <<'PY'
import sys
tmp, jobs, base, targets, refused = sys.argv[1:6]
def profile(name):
    last = {}  # output -> seconds (the last record of each output)
    for line in open(f"{tmp}/{name}/.ninja_log"):
        if line.startswith("#"):
            continue
        start, end, _, out, _ = line.rstrip("\n").split("\t")
        last[out] = (int(end) - int(start)) / 1000
    wall, cpu = (float(x) for x in open(f"{tmp}/{name}.times").read().split())
    compile_s = sum(s for out, s in last.items() if out.endswith(".o") or out.endswith(".gch"))
    steps = sum(last.values())
    top = sorted(((s, out) for out, s in last.items()), reverse=True)[:6]
    # Where the steps went: compiling the libraries and executables of src/
    # (and the generated forms), compiling the tests, linking the tests
    # (whose step includes gtest_discover_tests starting the executable), the rest.
    parts = {}
    for out, s in last.items():
        compiled = out.endswith(".o") or out.endswith(".gch")
        part = ("tests compile" if compiled else "tests link") if out.startswith("tests/") else \
               ("src compile" if compiled else "other")
        count, total = parts.get(part, (0, 0.0))
        parts[part] = (count + 1, total + s)
    return dict(wall=wall, cpu=cpu, steps=steps, compile=compile_s, count=len(last), top=top, parts=parts)
b, n = profile("base"), profile("new")
print(f"clean build of {targets}, -j {jobs}, no ccache; base {base} against the tree as it is")
print(f"{'':28}{'base':>10}{'new':>10}{'new/base':>10}")
for key, label in (("wall", "wall s"), ("cpu", "processor s (user+sys)"), ("steps", "sum of ninja step s"),
                   ("compile", "  of which compiling s")):
    print(f"{label:28}{b[key]:10.0f}{n[key]:10.0f}{n[key] / b[key]:10.2f}")
print(f"{'ninja steps':28}{b['count']:10d}{n['count']:10d}")
for part in ("src compile", "tests compile", "tests link", "other"):
    (bc, bs), (nc, ns) = b["parts"].get(part, (0, 0.0)), n["parts"].get(part, (0, 0.0))
    print(f"{'  ' + part + ' (steps, s)':28}{f'{bc} {bs:.0f}':>10}{f'{nc} {ns:.0f}':>10}")
print(f"goal: new/base at most 0.50; precompiled headers refused in the new build: {refused}")
for name, p in (("base", b), ("new", n)):
    print(f"  {name} slowest: " + ", ".join(f"{out.split('/')[-1]} {s:.0f} s" for s, out in p["top"]))
PY
