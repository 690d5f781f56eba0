#!/usr/bin/env bash
# The inputs of the reliability review, each with its expected exit code and
# message: no signal, no "internal error", nothing written, the user's files
# intact, no hang (every command runs under a time limit; two-rank cases too).
#   reliability.sh ROLLCHECK SOURCE_DIR TMP_DIR
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
cd "$tmp" || exit 1
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
# Loads the model cannot represent: refused up front, on every rank.
expect 2 "too small" -- "$bin" crease --load-per-length 3
expect 2 "too small" -- "$bin" hertz --model plane-strain --load 1e-7
expect 2 "too small" -- "$bin" hertz --load 1e-15
expect 2 "too small" -- mpirun -n 2 "$bin" hertz --model plane-strain --load 1e-7
# A small load the model can represent is valid physics: it solves.
expect 0 "p0" -- "$bin" hertz --load 1e-9 --json -
# Integers are range-checked before narrowing.
printf '[scene]\nkind = "mesh"\nbody = "oloid"\npoints = 4294967696\n' > points.toml
expect 2 "points.*100000" -- "$bin" run points.toml
printf '[scene]\nkind = "hertz"\ndegree = 4294967297\n' > degree.toml
expect 2 "degree" -- "$bin" run degree.toml
printf '[scene]\nkind = "crease"\nrefine = -9223372036854775808\n' > refine.toml
expect 2 "refine" -- "$bin" run refine.toml
expect 2 "refine" -- "$bin" hertz --refine -5
expect 2 "timeout" -- "$bin" batch points.toml --timeout -1
# PETSc options: before `--` named; a value PETSc rejects is not silently ignored.
expect 2 "PETSc option" -- "$bin" hertz --model axi -hertz_ksp_type cg
expect 2 "KSP type nonsense" -- "$bin" hertz --model axi --refine 0 -- -hertz_ksp_type nonsense
# On 2 ranks too: PETSc's own handler would exit(0) rank 1 without MPI_Finalize.
expect 2 "KSP type nonsense" -- mpirun -n 2 "$bin" hertz --model axi --refine 0 -- -hertz_ksp_type nonsense
expect 2 "rejected the solver options.*nonsense" -- "$bin" hertz --model axi --refine 0 --petsc-options '-hertz_pc_type nonsense'
# Resources: declared counts against the file; sizes with their limit.
printf 'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n' > huge.off
expect 2 "huge.off" -- "$bin" mesh --mesh huge.off
expect 2 "points.*100000" -- "$bin" mesh --points 1000000000
expect 2 "steps" -- "$bin" oracle --oracle approx --steps 1000000000
# Lost data: a user's file or folder is never replaced.
echo precious > precious.txt
expect 2 "precious.txt" -- "$bin" fem-sds --body cylinder --orientations 1 --out precious.txt
[[ $(cat precious.txt) == precious ]] || { echo "FAIL: precious.txt changed"; fail=1; }
mkdir -p victim/sub && echo notes > victim/notes.txt
"$bin" -q batch points.toml --out store > /dev/null 2>&1
printf '[scene]\nkind = "mesh"\nbody = "oloid"\npoints = 100\n' > small.toml
"$bin" -q batch small.toml --out store > /dev/null 2>&1
expect 2 "victim" -- "$bin" report --from store/results.h5 --out victim
[[ -f victim/notes.txt && -d victim/sub ]] || { echo "FAIL: report removed the user's files"; fail=1; }
# Output paths: a folder where a file goes, a missing folder: exit 2 naming it, before computing.
mkdir -p xd/f.xdmf
expect 2 "xd/f.xdmf" -- "$bin" hertz --xdmf xd/f.xdmf
expect 2 "xd/f.xdmf" -- mpirun -n 2 "$bin" hertz --xdmf xd/f.xdmf
expect 2 "nonexistent" -- "$bin" hertz --model 3d --json /nonexistent/x.json
ls -A xd | grep -q tmp && { echo "FAIL: scratch left in xd/"; fail=1; }
# A batch refused for bad input (a missing case file) leaves nothing: no folder, no lock.
expect 2 "nothing_here.toml" -- "$bin" batch nothing_here.toml --out refused
[[ -e refused ]] && { echo "FAIL: a refused batch left refused/"; ls -A refused; fail=1; }
exit $fail
