#!/usr/bin/env bash
# A linear solver the PETSc options choose that cannot run on 2 ranks (PETSc's
# own LU on an MPI matrix) is refused by every rank with PETSc's reason and
# exit 2, not PETSc's trace and mpirun's "exiting improperly" (issue 58).
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
out=$(timeout 300 mpirun -n 2 --oversubscribe "$bin" -q hertz --json "$tmp/lu.json" \
  -- -hertz_pc_type lu -hertz_pc_factor_mat_solver_type petsc 2>&1); rc=$?
check "[[ $rc -eq 2 ]]" "exit $rc, not 2: $out"
check "grep -q 'PETSc cannot run the linear solver the options chose (prefix hertz_): MatSolverType petsc does not support matrix type mpiaij' <<<\"\$out\"" "PETSc's reason not named: $out"
check "! grep -q 'exiting improperly\|PETSC ERROR' <<<\"\$out\"" "PETSc's trace or an improper exit: $out"
check "[[ ! -e '$tmp/lu.json' ]]" "a result was written"
exit $fail
