#!/usr/bin/env bash
# Benchmark (not a test): the BLAS's threads (core/blas_threads.h). The
# audit's FEM-SDS search (its heaviest command, c17) with the environment
# naming no count (rollcheck asks OpenBLAS for one thread) against
# OPENBLAS_NUM_THREADS=2 (OpenBLAS's own default on 2 CPUs): alone, and two
# copies side by side, as the main job runs its commands. Prints each
# process's wall and CPU seconds (user + system) and the ratios.
#   bash scripts/bench/bench_blas_threads.sh [BUILD_CLI_FOLDER]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
cli=${1:-$here/build/src/cli}
unset OPENBLAS_NUM_THREADS GOTO_NUM_THREADS OMP_NUM_THREADS
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
command=("$cli/rollcheck-fem" -q optimize --score fem-sds --oracle rolling --family centre-line --points 60
         --max-evaluations 3 --replicates 2 --sweep-points 2 --derivatives start --json -)
# timed FILE [VAR=VALUE]: the command's "wall cpu" seconds into FILE.
timed() {
  local file=$1; shift
  env "$@" /usr/bin/time -f "%e %U %S" -o "$file.t" "${command[@]}" > /dev/null 2>&1
  awk '{printf "%.2f %.2f\n", $1, $2 + $3}' "$file.t" > "$file"
}
timed "$tmp/one"
timed "$tmp/two" OPENBLAS_NUM_THREADS=2
timed "$tmp/one_a" & timed "$tmp/one_b" & wait
timed "$tmp/two_a" OPENBLAS_NUM_THREADS=2 & timed "$tmp/two_b" OPENBLAS_NUM_THREADS=2 & wait
row() { # LABEL ONE_FILE TWO_FILE
  read -r w1 c1 < "$2"; read -r w2 c2 < "$3"
  printf '%-26s %8.2f %8.2f %10.2f %8.2f %8.2fx %8.2fx\n' "$1" "$w1" "$c1" "$w2" "$c2" \
    "$(echo "$w2 / $w1" | bc -l)" "$(echo "$c2 / $c1" | bc -l)"
}
printf '%-26s %8s %8s %10s %8s %9s %9s\n' "c17 (seconds)" "wall" "CPU" "wall" "CPU" "wall" "CPU"
printf '%-26s %17s %19s %19s\n' "" "one thread" "OPENBLAS_NUM_THREADS=2" "ratio 2 / one"
row "alone" "$tmp/one" "$tmp/two"
row "two side by side (first)" "$tmp/one_a" "$tmp/two_a"
row "two side by side (second)" "$tmp/one_b" "$tmp/two_b"
