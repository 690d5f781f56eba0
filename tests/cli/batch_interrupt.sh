#!/usr/bin/env bash
# Killing a batch mid-run loses nothing finished and leaves no corrupt file:
# SIGINT once a case has finished (the running case is dropped, the store is
# written from what finished, exit 130), then SIGKILL once another has
# finished (no case process outlives the batch), then a re-run completes the
# batch, skipping every case that finished, with a store that h5py reads.
# The signals are sent when a result appears on disk, not after a fixed
# time, so the test holds on a loaded machine.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
py=/usr/bin/python3
rm -rf "$tmp"; mkdir -p "$tmp/cases"
finished() { ls "$tmp"/out/cases/*/result.json 2>/dev/null | wc -l; }
wait_for_results() { # wait_for_results N PID: until N results exist (or the batch ended)
  for _ in $(seq 1 1200); do
    [[ $(finished) -ge $1 ]] && return 0
    kill -0 "$2" 2>/dev/null || return 1
    sleep 0.1
  done
  return 1
}
store_ok() { # store_ok MIN_CASES: h5py reads the store, every case in it is ok
  $py - "$tmp/out/results.h5" "$1" <<'PY'
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    cases = f["cases"]
    assert len(cases) >= int(sys.argv[2]), list(cases)
    for name in cases:
        assert cases[name].attrs["status"] == "ok", name
        assert cases[name + "/summary/n_faces"][()] > 0, name
PY
}

for i in 1 2 3 4 5; do
  printf '[scene]\nkind = "mesh"\nbody = "sphere"\nsubdivisions = 6\nradius_m = %s\n' "1.$i" > "$tmp/cases/sphere_$i.toml"
done

# 1. SIGINT after the first case finished, one worker: the second is running.
"$bin" batch "$tmp/cases" -j 1 --out "$tmp/out" > "$tmp/int.out" 2> "$tmp/int.err" &
pid=$!
wait_for_results 1 $pid || echo "FAIL: no case finished before the batch ended"
kill -INT $pid
wait $pid
rc=$?
check '[[ $rc -eq 130 ]]' "SIGINT: exit code $rc, expected 130"
check 'grep -qE "interrupted|not run" "$tmp/int.out"' "SIGINT: no interrupted case in the table"
after_int=$(finished)
check '[[ $after_int -ge 1 && $after_int -lt 5 ]]' "SIGINT: $after_int results"
check '! ls -A "$tmp/out/cases" | grep -qE "\.part$|\.old$|^\."' "SIGINT: work folders left behind"
store_ok "$after_int" || { echo "FAIL: store after SIGINT"; fail=1; }

# 2. SIGKILL after one more case finished: no case process survives it.
"$bin" batch "$tmp/cases" -j 2 --out "$tmp/out" > "$tmp/kill.out" 2>&1 &
pid=$!
wait_for_results $((after_int + 1)) $pid || echo "FAIL: no case finished before the batch ended"
kill -KILL $pid
wait $pid 2>/dev/null
sleep 1
check '! pgrep -f "rollcheck run $tmp" > /dev/null' "SIGKILL: case processes outlived the batch"
after_kill=$(finished)
store_ok "$after_int" || { echo "FAIL: store after SIGKILL"; fail=1; }

# 3. The re-run completes the batch and skips every finished case.
"$bin" batch "$tmp/cases" -j 2 --out "$tmp/out" > "$tmp/rerun.out" 2>&1
rc=$?
check '[[ $rc -eq 0 ]]' "re-run: exit code $rc"
check 'grep -qE "5 case\(s\): $((5 - after_kill)) computed, $after_kill skipped \(done earlier\), 0 failed" "$tmp/rerun.out"' \
  "re-run did not skip the $after_kill finished cases: $(grep 'case(s)' "$tmp/rerun.out")"
check '! ls -A "$tmp/out/cases" | grep -qE "\.part$|\.old$|^\."' "re-run: work folders left behind"
check '! ls -A "$tmp/out" | grep -q "tmp"' "re-run: temporary store files left behind"
store_ok 5 || { echo "FAIL: store after the re-run"; fail=1; }
exit $fail
