#!/usr/bin/env bash
# Benchmark (not a test) of what one third-party header costs a translation
# unit: for each header, a file that includes only it is compiled with the
# FEM library's flags (-O3, its defines and include paths, from BUILD's
# compile_commands.json) and the compiler's processor time (user + system)
# and the preprocessed lines are printed, the standard library's <vector>
# first as the yardstick. A file of ours pays the sum over what it includes.
#   bash scripts/bench/bench_headers.sh [BUILD]   (BUILD defaults to build/)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$here/build}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
/usr/bin/python3 - "$build/compile_commands.json" "$tmp" <<'PY'
import json, resource, shlex, subprocess, sys
commands, tmp = sys.argv[1], sys.argv[2]
entry = next(e for e in json.load(open(commands)) if "rollcheck_fem.dir" in e["command"] and e["file"].endswith(".cpp"))
words = shlex.split(entry["command"])
# The flags without the launcher, the compiler, the object and the source.
flags = [w for i, w in enumerate(words[1:], 1)
         if w not in ("-o", "-c") and words[i - 1] not in ("-o", "-c") and not w.endswith("ccache")]
compiler = next(w for w in words if not w.endswith("ccache"))
flags = [w for w in flags if w != compiler]
headers = ["vector", "nlohmann/json_fwd.hpp", "nlohmann/json.hpp", "fmt/format.h", "spdlog/spdlog.h", "CLI/CLI.hpp",
           "toml++/toml.h", "Eigen/Core", "Eigen/Dense", "mpi.h", "petscksp.h", "dolfinx/mesh/Mesh.h",
           "dolfinx/fem/Function.h", "gtest/gtest.h"]
print(f"{'header':26}{'processor s':>12}{'lines':>9}")
for header in headers:
    source = f"{tmp}/one.cpp"
    open(source, "w").write(f"#include <{header}>\n")
    lines = subprocess.run([compiler, *flags, "-E", source], capture_output=True, text=True).stdout.count("\n")
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run([compiler, *flags, "-c", source, "-o", f"{tmp}/one.o"], check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    print(f"{header:26}{cpu:12.2f}{lines:9d}")
PY
