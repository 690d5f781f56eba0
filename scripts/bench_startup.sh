#!/usr/bin/env bash
# Benchmark (not a test): whole-process wall time of commands that need no MPI
# against the same work in a command that starts MPI (as every command did
# before MPI became per-scene): `rollcheck --version` against `rollcheck hertz
# --help` (MPI started, nothing solved), and the approximate oracle on the
# published oloid mesh against the same oracle scene run from a case file by
# `rollcheck run` (which starts MPI). Prints the mean of N runs and the ratio.
#   bash scripts/bench_startup.sh [ROLLCHECK] [N]
set -euo pipefail
here=$(cd "$(dirname "$0")/.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
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
row() { # name, then the command without MPI, `::`, the command with MPI
  local name=$1; shift
  local fast=() slow=()
  while [[ $1 != :: ]]; do fast+=("$1"); shift; done; shift
  slow=("$@")
  local a b
  a=$(mean "${fast[@]}"); b=$(mean "${slow[@]}")
  printf '%-22s %10.4f s %10.4f s %7.1fx\n' "$name" "$a" "$b" "$(echo "$b / $a" | bc -l)"
}
printf '%-22s %12s %12s %8s\n' "" "no MPI" "with MPI" "ratio"
row "version / help" "$bin" --version :: "$bin" hertz --help
row "approximate oracle" "$bin" oracle --oracle approx --mesh "$mesh" --paper-compat --metrics cds --json /dev/null \
  :: "$bin" run "$tmp/approx.toml" --json /dev/null
