#!/usr/bin/env bash
# Benchmark (not a test) of what one third-party header costs a translation
# unit: for each header, a file that includes only it is compiled with the
# FEM library's flags (-O3, its defines and include paths, from BUILD's
# compile_commands.json) and the compiler's processor time (user + system)
# and the preprocessed lines are printed, the standard library's <vector>
# first as the yardstick, and how many of our .cpp files (src/, tests/)
# include it, directly or through our headers. A file of ours pays the sum
# over what it includes.
#   bash scripts/bench/bench_headers.sh [BUILD]   (BUILD defaults to build/)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 - "$build/compile_commands.json" "$tmp" "$here" <<'PY'
import functools, json, pathlib, re, resource, shlex, subprocess, sys
commands, tmp, here = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
include = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)
ours = {p: p.read_text() for folder in ("src", "tests") for p in (here / folder).rglob("*") if p.suffix in (".h", ".cpp")}

@functools.cache
def reached(path):
    """The third-party headers PATH includes, directly or through our headers."""
    found = set()
    for kind, name in include.findall(ours[path]):
        local = [p for p in (here / "src" / name, path.parent / name, here / "tests" / name) if p in ours]
        if kind == '"' and local:
            found |= reached(local[0]) if local[0] != path else set()
        else:
            found.add(name)
    return frozenset(found)

sources = [p for p in ours if p.suffix == ".cpp"]
entry = next(e for e in json.load(open(commands)) if "rollcheck_fem.dir" in e["command"] and e["file"].endswith(".cpp"))
words = shlex.split(entry["command"])
# The flags without the launcher, the compiler, the object and the source.
flags = [w for i, w in enumerate(words[1:], 1)
         if w not in ("-o", "-c") and words[i - 1] not in ("-o", "-c") and not w.endswith("ccache")]
compiler = next(w for w in words if not w.endswith("ccache"))
flags = [w for w in flags if w != compiler]
# Each header with the prefix by which our includes of its library are counted.
headers = [("vector", "vector"), ("nlohmann/json_fwd.hpp", "nlohmann/json_fwd"), ("nlohmann/json.hpp", "nlohmann/json.hpp"),
           ("fmt/format.h", "fmt/"), ("spdlog/spdlog.h", "spdlog/"), ("CLI/CLI.hpp", "CLI/"), ("toml++/toml.h", "toml++/"),
           ("Eigen/Core", "Eigen/"), ("Eigen/Dense", "Eigen/Dense"), ("mpi.h", "mpi.h"), ("petscksp.h", "petsc"),
           ("dolfinx/mesh/Mesh.h", "dolfinx"), ("dolfinx/fem/Function.h", "dolfinx"), ("gtest/gtest.h", "gtest/")]
print(f"{'header':26}{'processor s':>12}{'lines':>9}{'our files':>10} (of {len(sources)})")
for header, prefix in headers:
    source = f"{tmp}/one.cpp"
    open(source, "w").write(f"#include <{header}>\n")
    lines = subprocess.run([compiler, *flags, "-E", source], capture_output=True, text=True).stdout.count("\n")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([compiler, *flags, "-c", source, "-o", f"{tmp}/one.o"], check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    including = sum(1 for p in sources if any(h.startswith(prefix) for h in reached(p)))
    print(f"{header:26}{cpu:12.2f}{lines:9d}{including:10d}")
PY
