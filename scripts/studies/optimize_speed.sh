#!/usr/bin/env bash
# The speed section of docs/results/optimize.md: `rollcheck optimize` on 2
# threads, (1) the local CDS search of the preprint's family at 100, 200 and
# 300 points per circle, and (2) the fast scores against issue 17's budgets, a
# local search (BOBYQA, at most 400 evaluations) within 300 s and a global one
# (DIRECT-L, 1000 evaluations) within 1800 s, each timed as the whole command.
# The global searches of the rigid scores at matched face count and of U (2-5
# minutes each in their last run) are left out to keep the script within 10
# minutes: their last rows are in docs/notes/optimize-tables.md. Each run's
# JSON, its options (NAME.args.json) and /usr/bin/time's wall and CPU seconds
# (NAME.time.json) go to OUT_DIR (default results/optimize-speed); then
# scripts/studies/optimize_speed_page.py writes the section from those files.
# Usage: scripts/studies/optimize_speed.sh [ROLLCHECK_BINARY] [OUT_DIR]
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
bin=${1:-$here/build/src/cli/rollcheck}
out=${2:-$here/results/optimize-speed}
mkdir -p "$out"
export OPENBLAS_NUM_THREADS=1
optimize() { # NAME OPTIONS...: `rollcheck optimize OPTIONS --threads 2` with its JSON, options and times in $out
  local name=$1; shift
  printf '{"args": "%s"}\n' "$*" > "$out/$name.args.json"
  /usr/bin/time -f '{"wall_s": %e, "user_s": %U, "system_s": %S}' -o "$out/$name.time.json" \
    "$bin" -q optimize "$@" --threads 2 --json "$out/$name.json" > "$out/$name.log" 2>&1 \
    || { echo "optimize $* failed: see $out/$name.log" >&2; exit 1; }
}
for points in 100 200 300; do
  optimize "resolution_$points" --score cds --oracle approx --paper-compat --family paper --points "$points" \
    --max-evaluations 100
done
local_search="--method bobyqa --max-evaluations 400"
global_search="--method direct-l --max-evaluations 1000"
# name: score options (each run at the genome's points and, suffixed _faces, at matched face count)
declare -A scores=(
  [cds_approx]="--score cds --oracle approx --paper-compat --points 300"
  [sds_approx]="--score sds --oracle approx --paper-compat --points 300"
  [cds_rigid]="--score cds --oracle rigid --paper-compat --points 300 --replicates 16"
  [sds_rigid]="--score sds --oracle rigid --paper-compat --points 300 --replicates 16"
  [uniformity]="--score uniformity --oracle rolling --family centre-line --points 100")
for name in cds_approx sds_approx cds_rigid sds_rigid uniformity; do
  # shellcheck disable=SC2086  # the options are words
  optimize "${name}_points_local" ${scores[$name]} $local_search
  # shellcheck disable=SC2086
  optimize "${name}_faces_local" ${scores[$name]} --matched-resolution $local_search
done
for name in cds_approx sds_approx cds_rigid sds_rigid; do
  # shellcheck disable=SC2086
  optimize "${name}_points_global" ${scores[$name]} $global_search
done
for name in cds_approx sds_approx; do
  # shellcheck disable=SC2086
  optimize "${name}_faces_global" ${scores[$name]} --matched-resolution $global_search
done
/usr/bin/python3 "$here/scripts/studies/optimize_speed_page.py" "$out" "$("$bin" --version | head -1)" \
  "$here/docs/results/optimize.md"
