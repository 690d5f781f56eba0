#!/usr/bin/env bash
# `rollcheck batch` with failing cases: 4 small cases on 2 workers, one
# malformed: 3 succeed, 1 is reported with its message, the exit code says 1
# failed, the store holds all 4 and h5py reads it. A re-run skips the 3 done
# cases, --force recomputes them; a case whose process fails is reported with
# the process's own error; bad arguments exit 2.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
py=/usr/bin/python3
rm -rf "$tmp"; mkdir -p "$tmp/cases"

printf '[scene]\nkind = "mesh"\nbody = "oloid"\npoints = 100\n' > "$tmp/cases/oloid.toml"
printf '[scene]\nkind = "mesh"\nbody = "cylinder"\n' > "$tmp/cases/cylinder.toml"
printf '[scene]\nkind = "mesh"\nbody = "sphere"\nsubdivisions = 2\n' > "$tmp/cases/sphere.toml"
printf '[scene\nkind = "mesh"\n' > "$tmp/cases/malformed.toml"

"$bin" batch "$tmp/cases" -j 2 --out "$tmp/out" --json "$tmp/first.json" > "$tmp/first.out" 2> "$tmp/first.err"
rc=$?
check '[[ $rc -eq 1 ]]' "exit code $rc, expected 1 (one failed case)"
check 'grep -qE "^malformed +- +FAILED .*malformed.toml.*malformed TOML" "$tmp/first.out"' "malformed case not reported with its message"
check '[[ $(grep -cE "^(oloid|cylinder|sphere) +mesh +ok " "$tmp/first.out") -eq 3 ]]' "three cases not ok"
check 'grep -q "3 computed, 0 skipped (done earlier), 1 failed" "$tmp/first.out"' "totals line"
check 'grep -q "\[3/3\] ok" "$tmp/first.err"' "progress lines"
$py - "$tmp/out/results.h5" <<'PY' || { echo "FAIL: store"; fail=1; }
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    cases = f["cases"]
    assert sorted(cases) == ["cylinder", "malformed", "oloid", "sphere"], list(cases)
    status = {n: cases[n].attrs["status"] for n in cases}
    assert status == {"cylinder": "ok", "malformed": "failed", "oloid": "ok", "sphere": "ok"}, status
    assert "malformed TOML" in cases["malformed"].attrs["message"]
    assert cases["oloid/parameters"].attrs["points"] == 100
    assert cases["oloid/summary/n_faces"][()] > 0 and bool(cases["oloid/summary/convex"][()])
    assert cases["oloid/summary/centre_of_mass_m"].shape == (3,)
    assert f.attrs["n_ok"] == 3 and f.attrs["n_failed"] == 1
PY
check '[[ $($py -c "import json,sys; print(json.load(open(sys.argv[1]))[\"failed\"])" "$tmp/first.json") == 1 ]]' "--json summary"

# Re-run: the finished cases are skipped, the malformed one fails again.
"$bin" batch "$tmp/cases" -j 2 --out "$tmp/out" > "$tmp/second.out" 2>&1
rc=$?
check '[[ $rc -eq 1 ]]' "re-run exit code $rc"
check 'grep -q "0 computed, 3 skipped (done earlier), 1 failed" "$tmp/second.out"' "re-run did not skip the done cases"
"$bin" batch "$tmp/cases/oloid.toml" "$tmp/cases/sphere.toml" --force --out "$tmp/out" > "$tmp/force.out" 2>&1
check '[[ $? -eq 0 ]] && grep -q "2 computed, 0 skipped" "$tmp/force.out"' "--force did not recompute"
check '! ls -A "$tmp/out/cases" | grep -qE "\.part$|\.old$|^\."' "work folders left behind"

# A case whose process fails (valid keys, a malformed mesh file beside it):
# its own error message, exit code 1.
printf 'v 0 0 0\nf 1 2 3\n' > "$tmp/broken.obj"
printf '[scene]\nkind = "mesh"\nmesh_file = "broken.obj"\n' > "$tmp/negative.toml"
"$bin" batch "$tmp/negative.toml" --out "$tmp/out2" > "$tmp/negative.out" 2>&1
rc=$?
check '[[ $rc -eq 1 ]]' "failing process: exit code $rc"
check 'grep -qE "negative +mesh +FAILED .*broken.obj" "$tmp/negative.out"' "failing process: message lacks the scene's error"
check '[[ -s $(ls -d "$tmp"/out2/cases/*/)log.txt ]]' "failing process: log not kept"

# Bad arguments: exit 2 before anything runs.
"$bin" batch "$tmp/nothing_here.toml" --out "$tmp/out3" > "$tmp/badarg.out" 2>&1
check '[[ $? -eq 2 ]] && grep -q "nothing_here.toml" "$tmp/badarg.out"' "missing argument not an input error"
"$bin" batch "$tmp/cases" -j -1 --out "$tmp/out3" > "$tmp/badj.out" 2>&1
check '[[ $? -eq 2 ]] && grep -q "jobs: Value -1 not in range 0 to 1024" "$tmp/badj.out"' "-j -1 not an input error"
exit $fail
