#!/usr/bin/env bash
# Issue 58, the output side: every bad output path is refused (exit 2, named)
# before anything is computed, leaving every file byte-identical; a full disk
# is exit 1 naming the file with the previous file intact; a batch into a
# folder holding the user's files leaves them untouched and refuses a
# results.h5 it did not write; a changed mesh file is recomputed; an
# interrupted `batch --force` keeps every case in its store.
#   output_safety.sh ROLLCHECK SOURCE_DIR TMP_DIR
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
py=/usr/bin/python3
rm -rf "$tmp"; mkdir -p "$tmp"
cd "$tmp" || exit 1
# fingerprint FOLDER: every file below it with its checksum, sorted.
fingerprint() { (cd "$1" && find . -type f ! -name .lock ! -name .rollcheck-output -print0 | sort -z | xargs -0 -r sha256sum); }

# 1. Bad output paths: exit 2 naming the path, before computing (a timeout
#    of 60 s bounds commands that compute for minutes when not refused).
mkdir -p userdir && echo "the user's" > userdir/notes.txt
mkdir -p hdir && echo "user,csv" > hdir/hertz_penalty.csv
echo "not json" > bad_audit.json
before=$(fingerprint .)
expect 2 "/nonexistent" -- timeout 60 "$bin" audit --quick --markdown /nonexistent/a.md
expect 2 "/nonexistent" -- timeout 60 "$bin" fem-sds --body cylinder --out /nonexistent/d
expect 2 "userdir" -- timeout 60 "$bin" fem-sds --body cylinder --out userdir
expect 2 "notes.txt" -- timeout 60 "$bin" fem-sds --body cylinder --out userdir/notes.txt
expect 2 "/nonexistent" -- timeout 60 "$bin" search --hdf5 /nonexistent/x.h5
expect 2 "hdir" -- timeout 60 "$bin" search --hdf5 hdir
expect 2 "/nonexistent" -- timeout 60 "$bin" mesh --points 200 --out /nonexistent/v.msh
expect 2 "/nonexistent" -- timeout 60 "$bin" mesh --out /nonexistent/v.obj
expect 2 "/dev/null" -- timeout 60 "$bin" mesh --json /dev/null
expect 2 "hertz_penalty.csv" -- timeout 60 "$bin" hertz --study penalty --study-models axi --out hdir
expect 2 "bad_audit.json" -- timeout 60 "$bin" validate --audit bad_audit.json --out vout
check '[[ ! -e vout ]]' "validate refused for its --audit still made its --out folder"
check '[[ "$(fingerprint .)" == "$before" ]]' "a refused command changed a file"
check '! ls -A . hdir userdir | grep -q "tmp"' "a refused command left a temporary file"

# 2. A full disk: exit 1 naming the file, the previous file byte-identical.
#    On a 2 MB tmpfs, where the test may mount one (root); else skipped.
full=$tmp/full; mkdir -p "$full"
if mount -t tmpfs -o size=2M tmpfs "$full" 2>/dev/null; then
  echo previous > "$full/m.json"; echo previous > "$full/v.msh"
  dd if=/dev/zero of="$full/filler" bs=4k 2>/dev/null
  expect 1 "m.json" -- "$bin" mesh --points 200 --json "$full/m.json"
  expect 1 "v.msh" -- "$bin" mesh --points 200 --size 0.5 --out "$full/v.msh"
  check '[[ "$(cat "$full/m.json")" == previous && "$(cat "$full/v.msh")" == previous ]]' "full disk: a previous file changed"
  check '[[ $(ls -A "$full" | wc -l) -eq 3 ]]' "full disk: temporary files left: $(ls -A "$full")"
  umount "$full"
else
  echo "SKIP: full-disk checks (cannot mount a tmpfs here; they need root)"
fi
expect 1 "stdout" -- bash -c "'$bin' oracle --per-face --json - > /dev/full"

# 3. A batch into a folder holding the user's files leaves them untouched.
mkdir -p cases
printf '[scene]\nkind = "mesh"\nbody = "sphere"\nsubdivisions = 2\n' > cases/a.toml
printf '[scene]\nkind = "mesh"\nbody = "sphere"\nsubdivisions = 3\n' > cases/b.toml
mkdir -p out/cases/r.part
echo "KEY=" > out/.env.tmpl; echo draft > out/.draft.tmp; : > out/cases/.gitkeep
echo plan > out/cases/plan.old; echo "1,2" > out/cases/r.part/data.csv
users=$(fingerprint out)
expect 0 "2 computed" -- "$bin" batch cases --out out
expect 0 "2 skipped" -- "$bin" batch cases --out out
expect 0 "2 computed" -- "$bin" batch cases --out out --force
check '[[ "$(fingerprint out | grep -E "env.tmpl|draft.tmp|gitkeep|plan.old|data.csv")" == "$users" ]]' \
  "batch changed the user's files"
check '[[ -f out/results.h5 ]]' "batch wrote no store"
# A results.h5 rollcheck did not write is refused by name, before any case runs.
mkdir -p out2 && echo "the user's store" > out2/results.h5
expect 2 "results.h5" -- "$bin" batch cases --out out2
check '[[ "$(cat out2/results.h5)" == "the user'"'"'s store" && ! -e out2/cases ]]' "batch replaced a user's results.h5"

# 4. A rerun after a mesh file changes recomputes that case.
"$bin" -q mesh --body sphere --subdivisions 1 --out body.obj
printf '[scene]\nkind = "mesh"\nmesh_file = "body.obj"\n' > mesh_case.toml
expect 0 "1 computed" -- "$bin" batch mesh_case.toml --out mout
expect 0 "1 skipped" -- "$bin" batch mesh_case.toml --out mout
"$bin" -q mesh --body sphere --subdivisions 3 --out body.obj
expect 0 "1 computed" -- "$bin" batch mesh_case.toml --out mout
$py - mout/results.h5 <<'PY' || { echo "FAIL: the store holds the old mesh's result"; fail=1; }
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    n = f["cases/mesh_case/summary/n_faces"][()]
    assert n == 20 * 4 ** 3, n
PY

# 5. SIGTERM during `batch --force`: the store keeps every case, the finished
#    one recomputed and the others with their earlier results.
for i in 1 2 3 4; do
  printf '[scene]\nkind = "mesh"\nbody = "sphere"\nsubdivisions = 6\nradius_m = %s\n' "1.$i" > "cases/s$i.toml"
done
"$bin" -q batch cases --out fout > /dev/null 2>&1
touch stamp; sleep 1
"$bin" batch cases -j 1 --out fout --force > force.out 2>&1 &
pid=$!
for _ in $(seq 1 1200); do
  [[ -n $(find fout/cases -name result.json -newer stamp) ]] && break
  kill -0 $pid 2>/dev/null || break
  sleep 0.1
done
kill -TERM $pid; wait $pid; rc=$?
check '[[ $rc -eq 130 ]]' "SIGTERM: exit code $rc, expected 130"
$py - fout/results.h5 <<'PY' || { echo "FAIL: the interrupted --force store lost cases"; fail=1; }
import sys, h5py
with h5py.File(sys.argv[1], "r") as f:
    assert len(f["cases"]) == 6, list(f["cases"])
    assert all(f["cases"][c].attrs["status"] == "ok" for c in f["cases"])
    assert bool(f.attrs["interrupted"])
PY
exit $fail
