#!/usr/bin/env bash
# `mpirun -n 2 rollcheck batch`: rank 0 hands the cases out to both ranks,
# each runs its share in its own processes, rank 0 alone reports and writes
# the store; a failed case still sets the exit code.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
py=/usr/bin/python3
rm -rf "$tmp"; mkdir -p "$tmp/cases"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for i in 1 2 3 4; do
  printf '[scene]\nkind = "mesh"\nbody = "sphere"\nsubdivisions = 3\nradius_m = %s\n' "1.$i" > "$tmp/cases/sphere_$i.toml"
done
printf '[scene]\nkind = "mesh"\nbody = "cube"\n' > "$tmp/cases/unknown_body.toml"

mpirun --allow-run-as-root --oversubscribe -n 2 "$bin" batch "$tmp/cases" -j 1 --out "$tmp/out" \
  > "$tmp/mpi.out" 2> "$tmp/mpi.err"
rc=$?
check '[[ $rc -eq 1 ]]' "exit code $rc, expected 1 (one failed case)"
check '[[ $(grep -c "^case " "$tmp/mpi.out") -eq 1 ]]' "the table is not printed once (by rank 0 alone)"
check 'grep -q "4 computed, 0 skipped (done earlier), 1 failed; 2 rank(s) x 1 worker(s)" "$tmp/mpi.out"' "totals line"
check 'grep -qE "^unknown_body +mesh +FAILED .*body.*cube" "$tmp/mpi.out"' "failed case not reported"
check 'grep -h "\"rank\": 0" "$tmp"/out/cases/*/result.json > /dev/null' "rank 0 ran no case"
check 'grep -h "\"rank\": 1" "$tmp"/out/cases/*/result.json > /dev/null' "rank 1 ran no case"
$py - "$tmp/out/results.h5" <<'PY' || { echo "FAIL: store"; fail=1; }
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    status = {n: g.attrs["status"] for n, g in f["cases"].items()}
    assert list(status) == ["sphere_1", "sphere_2", "sphere_3", "sphere_4", "unknown_body"], list(status)
    assert list(status.values()).count("ok") == 4, status
    ranks = {int(g.attrs["rank"]) for n, g in f["cases"].items() if "rank" in g.attrs}
    assert ranks == {0, 1}, ranks
PY
exit $fail
