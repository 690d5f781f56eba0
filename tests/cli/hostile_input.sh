#!/usr/bin/env bash
# Hostile input (issue 58, the input side; issue 59's case-file rules): special
# files as meshes and case files, deep TOML, work-multiplying values beyond the
# work budget, values that were silently ignored, misleading mesh diagnoses.
# Each is refused with exit 2 and a message naming the input (or works).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; here=$2; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp/in"; in=$tmp/in

# Special files as a mesh, directly, through a symlink and through a case file.
ln -s /dev/zero "$in/z.stl"; ln -s /dev/urandom "$in/u.ply"; ln -s loop.obj "$in/loop.obj"
ln -s /proc/self/mem "$in/mem.obj"; mkfifo "$in/fifo.obj"; mkdir "$in/folder.obj"
expect 2 "'/dev/zero': unknown extension" -- "$bin" mesh --mesh /dev/zero
expect 2 "z.stl': is a character device" -- "$bin" mesh --mesh "$in/z.stl"
expect 2 "u.ply': is a character device" -- "$bin" mesh --mesh "$in/u.ply"
expect 2 "loop.obj': is a symbolic link loop" -- "$bin" mesh --mesh "$in/loop.obj"
expect 2 "mem.obj': cannot be read" -- "$bin" mesh --mesh "$in/mem.obj"
expect 2 "fifo.obj': is a fifo" -- "$bin" mesh --mesh "$in/fifo.obj"
expect 2 "folder.obj': is a directory" -- "$bin" mesh --mesh "$in/folder.obj"
printf '[scene]\nkind = "mesh"\nmesh_file = "z.stl"\n' > "$in/zero_mesh.toml"
expect 2 "z.stl': is a character device" -- "$bin" run "$in/zero_mesh.toml"

# Special files as a case file.
ln -s /dev/zero "$in/zero.toml"; ln -s cloop.toml "$in/cloop.toml"; mkfifo "$in/fifo.toml"; mkdir "$in/dir.toml"
ln -s /proc/self/mem "$in/mem.toml"
expect 2 "zero.toml': is a character device" -- "$bin" run "$in/zero.toml"
expect 2 "cloop.toml': is a symbolic link loop" -- "$bin" run "$in/cloop.toml"
expect 2 "fifo.toml': is a fifo" -- "$bin" run "$in/fifo.toml"
expect 2 "dir.toml': is a directory" -- "$bin" run "$in/dir.toml"
expect 2 "mem.toml': cannot be read" -- "$bin" run "$in/mem.toml"

# 50,000 nested tables or dotted keys: refused by the line cap, 2,000 by the nesting bound.
/usr/bin/python3 - "$in" <<'PY'
import sys
d = sys.argv[1]
head = '[scene]\nkind = "mesh"\n'
open(f"{d}/tables50k.toml", "w").write(head + "[" + ".".join(["a"] * 50000) + "]\n")
open(f"{d}/dotted50k.toml", "w").write(head + ".".join(["b"] * 50000) + " = 1\n")
open(f"{d}/tables2k.toml", "w").write(head + "[" + ".".join(["a"] * 2000) + "]\n")
open(f"{d}/arrays2k.toml", "w").write(head + "c = " + "[" * 2000 + "]" * 2000 + "\n")
open(f"{d}/manylines.toml", "w").write(head + "".join(f"[t{i}]\n" for i in range(50000)))
PY
expect 2 "tables50k.toml': line 3 is longer than 4096 bytes" -- "$bin" run "$in/tables50k.toml"
expect 2 "dotted50k.toml': line 3 is longer" -- "$bin" run "$in/dotted50k.toml"
expect 2 "tables2k.toml': line 3 nests" -- "$bin" run "$in/tables2k.toml"
expect 2 "arrays2k.toml': line 3 nests" -- "$bin" run "$in/arrays2k.toml"
expect 2 "manylines.toml': more than 10000 lines" -- "$bin" run "$in/manylines.toml"
# The batch names the case and goes on (its coordinator does not die).
expect 1 "tables2k.toml': line 3 nests" -- "$bin" batch "$in/tables2k.toml" --out "$tmp/batch"

# Work-multiplying values beyond the work budget.
expect 2 "sections.*\[4, 1024\], got 100000" -- "$bin" mesh --body uv-sphere --sections 100000
expect 2 "duration_s' / 'dt_s' asks for 1e\+09 rigid-body time steps" -- "$bin" oracle --oracle rigid --duration 1e6 --dt 1e-3
expect 2 "loops.*\[1, 100\], got 1000" -- "$bin" oracle --oracle rolling --loops 1000
expect 2 "samples.*\[2, 262144\], got 10000000" -- "$bin" fem-sds --samples-per-loop 10000000
expect 2 "option --samples-per-loop.*must be an integer, got '1e7'" -- "$bin" fem-sds --samples-per-loop 1e7
expect 2 "scan_directions_deg.*0 or in \[0.01, 360\]" -- "$bin" whole-body --scan-directions 1e-9
expect 2 "threads.*100000 not in range" -- "$bin" audit --quick --threads 100000
expect 2 "threads.*0 or in \[1, 256\]" -- "$bin" search --threads 100000
expect 2 "duration_s.*\(0, 2000\]" -- "$bin" optimize --oracle rigid --duration 1e6
expect 2 "ratio_max.*\[0.001, 1000\], got 1e\+300" -- "$bin" optimize --ratio-max 1e300

# PETSc options on a command line that needs no MPI end PETSc and MPI once.
for sub in "mesh --body sphere --subdivisions 1" "oracle --body sphere --subdivisions 1 --steps 10" \
           "search --grid quick --steps 20 --validate-top 0"; do
  out=$("$bin" $sub -- -foo 2>&1); rc=$?
  check "[[ $rc -eq 0 ]] && ! grep -q 'MPI_Finalize\|MPI_FINALIZE' <<<\"\$out\"" "$sub -- -foo: exit $rc: $out"
  check "grep -q 'PETSc option -foo was not used' <<<\"\$out\"" "$sub -- -foo names the unused option: $out"
done

# Values that were silently ignored or accepted.
expect 2 "option --radius: the value is empty" -- "$bin" mesh --radius ""
expect 2 "option --points: the value is empty" -- "$bin" mesh --points ""
expect 2 "option --mesh: the value is empty" -- "$bin" mesh --mesh ""
printf 'v nan 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 3 4\nf 1 4 2\nf 2 4 3\n' > "$in/nan.obj"
expect 2 "unknown option '--mesh'" -- "$bin" rim --mesh "$in/nan.obj"
expect 2 "nan.obj.: a vertex coordinate is NaN or infinite" -- "$bin" mesh --mesh "$in/nan.obj"
expect 2 "option --out \(out\) is written only with --score fem-sds" -- "$bin" search --out "$tmp/s"
expect 2 "timeout.*must be a finite number, got 'nan'" -- "$bin" batch "$here/cases/mesh_oloid.toml" --timeout nan --out "$tmp/b2"
expect 2 "--out.*must not be empty" -- "$bin" batch "$here/cases/mesh_oloid.toml" --out ""
expect 2 "seed.*got 9007199254740993" -- "$bin" rim --seed 9007199254740993
printf '[scene]\nkind = "mesh"\n[[check]]\npointer = "/n_faces"\nvalue = 1.0\nrel_tol = inf\nreference = "r"\n' > "$in/inf.toml"
expect 2 "inf.toml': check 1: max_abs and rel_tol must be finite" -- "$bin" run "$in/inf.toml"

# mesh --size is honoured (a different mesh per size) or refused by name.
"$bin" -q mesh --body sphere --subdivisions 2 --size 0.2 --out "$tmp/a.msh" || { echo "FAIL: --size 0.2"; fail=1; }
"$bin" -q mesh --body sphere --subdivisions 2 --size 0.1 --out "$tmp/b.msh" || { echo "FAIL: --size 0.1"; fail=1; }
check "! cmp -s '$tmp/a.msh' '$tmp/b.msh'" "--size 0.2 and 0.1 give the same .msh"
expect 2 "option --size.*1e\+300 m is larger than the body" -- "$bin" mesh --body sphere --size 1e300 --out "$tmp/c.msh"
expect 2 "option --size.*1e-06 m asks for about .* tetrahedra" -- "$bin" mesh --body sphere --size 1e-6 --out "$tmp/c.msh"
expect 2 "size 0.2 m asks for about .* gmsh inserted no node inside" -- "$bin" mesh --body oloid --points 100 --size 0.2 --out "$tmp/c.msh"

# report --from: a file that is not a results store.
printf 'not hdf5\n' > "$in/store.h5"
expect 2 "option --from '.*store.h5': is not an HDF5 file" -- "$bin" report --from "$in/store.h5" --out "$tmp/r"
/usr/bin/python3 -c "import h5py, sys; f = h5py.File(sys.argv[1], 'w'); f.attrs['layout'] = 'rollcheck-results-1'; f.create_group('cases')" "$in/empty.h5"
expect 2 "empty.h5': is an empty results store" -- "$bin" report --from "$in/empty.h5" --out "$tmp/r"
expect 2 "option --from '.*in': is not a regular file" -- "$bin" report --from "$in" --out "$tmp/r"

# Mesh diagnoses name the real problem.
tet='v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n'
printf "v 0 0 0\nv 1e300 0 0\nv 0 1e300 0\nv 0 0 1e300\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n" > "$in/huge.obj"
expect 2 "huge.obj': a vertex coordinate of 1e\+300 m" -- "$bin" mesh --mesh "$in/huge.obj"
printf "${tet}f 0 1 2\n" > "$in/zero_index.obj"
expect 2 "zero_index.obj:5: vertex index 0" -- "$bin" mesh --mesh "$in/zero_index.obj"
printf 'OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 -1 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n' > "$in/minus.off"
expect 2 "minus.off': face 1 refers to vertex index -1, but the 4 vertices are numbered 0 to 3" -- "$bin" mesh --mesh "$in/minus.off"
printf 'ply\nformat ascii 1.0\nelement vertex -4\nproperty float x\nend_header\n' > "$in/negative.ply"
expect 2 "negative.ply'.*'element vertex -4' does not declare a count" -- "$bin" mesh --mesh "$in/negative.ply"
printf "${tet}f 1 2 3\nf 1 2 4\nf 1 4 3\nf 2 3 4\n" > "$in/flipped.obj"
expect 2 "flipped.obj': faces are not consistently oriented" -- "$bin" mesh --mesh "$in/flipped.obj"

# Issue 59: every bad key at once; former keys name their successor.
printf '[scene]\nkind = "mesh"\nwibble = 1\nwobble = 2\nradius_m = -1.0\n' > "$in/bad_keys.toml"
expect 2 "unknown key 'wibble'; unknown key 'wobble'" -- "$bin" run "$in/bad_keys.toml"
out=$("$bin" run "$in/bad_keys.toml" 2>&1)
check "grep -q wibble <<<\"\$out\" && grep -q wobble <<<\"\$out\" && grep -q \"'radius_m' must be > 0\" <<<\"\$out\"" "every bad key named: $out"
printf '[scene]\nkind = "hertz"\nforce_n = 100.0\n' > "$in/former.toml"
expect 2 "key 'force_n' is now 'load_n'" -- "$bin" run "$in/former.toml"

# run --template KIND: a case file of the kind that reads back (only the
# --set key is unknown, so every key of the file is valid).
for kind in mesh oracle search optimize hertz fem-sds crease rim flat-rim rounded-end whole-body; do
  "$bin" run --template "$kind" > "$in/template_$kind.toml" 2>"$tmp/template.log" || { echo "FAIL: template $kind"; cat "$tmp/template.log"; fail=1; }
  sed -E 's/^# ([a-z0-9_]+ = )/\1/' "$in/template_$kind.toml" > "$in/uncommented_$kind.toml"
  for file in "$in/template_$kind.toml" "$in/uncommented_$kind.toml"; do
    out=$("$bin" run "$file" --set not_a_key=1 2>&1); rc=$?
    check "[[ $rc -eq 2 ]] && grep -q \"unknown key 'not_a_key'\" <<<\"\$out\" && [[ \$(grep -c 'unknown key\|must be' <<<\"\$out\") -eq 1 ]]" \
      "template of $kind does not read back ($file): $out"
  done
done
expect 2 "option --template: unknown scene kind 'nope'" -- "$bin" run --template nope
exit $fail
