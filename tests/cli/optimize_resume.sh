#!/usr/bin/env bash
# rollcheck optimize --out keeps the finished runs in OUT/evaluations.json: the
# same command rerun makes no oracle run and gives the same result (also with
# another --threads, which changes no run's value); with other --points none
# is reused; an --out folder holding a user's file exits 2 before computing.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OPENBLAS_NUM_THREADS=1
run() { "$bin" -q optimize --max-evaluations 12 --sweep-points 3 --out "$tmp/out" "$@"; }
run --points 60 --threads 1 --json "$tmp/first.json" > "$tmp/first.log" 2>&1 \
  || { echo "FAIL: first run"; cat "$tmp/first.log"; exit 1; }
check '[[ -s $tmp/out/evaluations.json ]]' "no evaluations.json in the output folder"
run --points 60 --threads 2 --json "$tmp/rerun.json" > "$tmp/rerun.log" 2>&1 \
  || { echo "FAIL: rerun"; cat "$tmp/rerun.log"; exit 1; }
run --points 61 --threads 1 --json "$tmp/other.json" > "$tmp/other.log" 2>&1 \
  || { echo "FAIL: run with other points"; cat "$tmp/other.log"; exit 1; }
/usr/bin/python3 - "$tmp/first.json" "$tmp/rerun.json" "$tmp/other.json" <<'PY' || fail=1
import json, sys
first, rerun, other = (json.load(open(p)) for p in sys.argv[1:])
assert first["oracle_runs"] > 0 and first["recalled_runs"] == 0, first["oracle_runs"]
assert rerun["oracle_runs"] == 0 and rerun["recalled_runs"] == first["oracle_runs"], (rerun["oracle_runs"], rerun["recalled_runs"])
strip = lambda r: {k: v for k, v in r.items() if k not in ("wall_s", "oracle_runs", "recalled_runs")}
assert strip(rerun) == strip(first), "the rerun's result differs"
assert other["recalled_runs"] == 0 and other["oracle_runs"] > 0, (other["oracle_runs"], other["recalled_runs"])
print("runs", first["oracle_runs"], "then", rerun["oracle_runs"], "new,", rerun["recalled_runs"], "recalled")
PY
mkdir -p "$tmp/users"; echo notes > "$tmp/users/notes.txt"
expect 2 "users.*rollcheck did not write" -- "$bin" -q optimize --max-evaluations 12 --out "$tmp/users"
check '[[ ! -e $tmp/users/evaluations.json ]]' "a user's folder received evaluations.json"
exit $fail
