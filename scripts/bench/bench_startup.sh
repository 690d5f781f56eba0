#!/usr/bin/env bash
# Benchmark (not a test): whole-process wall time of the fast subcommands in
# rollcheck (no FEM library loaded) against the same command in rollcheck-fem
# (the executable with DOLFINx, PETSc and gmsh, as every command ran before
# the split), and against the same work from a case file (`rollcheck run`,
# which starts MPI): `--version`, and the approximate oracle on the published
# oloid mesh; and that case run with Open MPI's singleton daemon (orted)
# against the isolated singleton rollcheck asks for (core/mpi_launch.h).
# Prints the mean of N runs and the ratios.
#   bash scripts/bench/bench_startup.sh [BUILD_CLI_FOLDER] [N]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cli=${1:-$here/build/src/cli}
n=${2:-20}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mesh="$here/meshes/reference/oloid_reference.obj"
printf '[scene]\nkind = "oracle"\nmesh_file = "%s"\noracle = "approx"\npaper_compat = true\nmetrics = "cds"\n' \
  "$mesh" > "$tmp/approx.toml"
mean() { # mean wall seconds of N runs of the command
  local start end
  start=$(date +%s.%N)
  for _ in $(seq "$n"); do "$@" > /dev/null 2>&1; done
  end=$(date +%s.%N)
  echo "($end - $start) / $n" | bc -l
}
approx=(oracle --oracle approx --mesh "$mesh" --paper-compat --metrics cds --json /dev/null)
v_fast=$(mean "$cli/rollcheck" --version); v_fem=$(mean "$cli/rollcheck-fem" --version)
a_fast=$(mean "$cli/rollcheck" "${approx[@]}"); a_fem=$(mean "$cli/rollcheck-fem" "${approx[@]}")
a_run=$(mean "$cli/rollcheck" run "$tmp/approx.toml" --json /dev/null)
printf '%-20s %12s %14s %8s %16s %8s\n' "" "rollcheck" "rollcheck-fem" "ratio" "run CASE (MPI)" "ratio"
printf '%-20s %10.4f s %12.4f s %7.1fx\n' "--version" "$v_fast" "$v_fem" "$(echo "$v_fem / $v_fast" | bc -l)"
printf '%-20s %10.4f s %12.4f s %7.1fx %14.4f s %7.1fx\n' "approximate oracle" "$a_fast" "$a_fem" \
  "$(echo "$a_fem / $a_fast" | bc -l)" "$a_run" "$(echo "$a_run / $a_fast" | bc -l)"
a_daemon=$(OMPI_MCA_ess_singleton_isolated=0 mean "$cli/rollcheck" run "$tmp/approx.toml" --json /dev/null)
printf '%-20s %12s %14s %8s\n' "" "isolated" "with orted" "ratio"
printf '%-20s %10.4f s %12.4f s %7.2fx\n' "run CASE (MPI)" "$a_run" "$a_daemon" "$(echo "$a_run / $a_daemon" | bc -l)"
