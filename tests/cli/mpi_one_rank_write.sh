#!/usr/bin/env bash
# MPI: an output write that fails on one rank only ends every rank with exit 1
# and the file named (fem/first_failure.h: the ranks agree on each collective
# write step and on the command's outcome), never a hang. The failure is real:
# one rank runs under a file-size limit (`ulimit -f 0` with SIGXFSZ ignored),
# so its writes to regular files fail with EFBIG, as on a disk that fills while
# that rank writes. Every run is bounded by `timeout`: a hang fails the test.
#   rank 1 limited, `hertz --xdmf`: its part of NAME.h5 (DOLFINx's collective
#     HDF5 writer) fails while rank 0's succeeds;
#   rank 0 limited, `hertz --json`: the summary, which rank 0 alone writes, fails.
set -u
source "$(dirname "$0")/lib.sh"
bin=$1; tmp=$3
rm -rf "$tmp"; mkdir -p "$tmp"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1
# Each rank writes its own part of the .h5 (OpenMPI's default lets rank 0
# gather and write every rank's part). The limit must meet only our output:
# no shared-memory transport and no shared-memory file pointer, whose backing
# files it would refuse too (OpenMPI's MPI_File_open then deadlocks inside).
export OMPI_MCA_fcoll=individual OMPI_MCA_btl=self,tcp OMPI_MCA_sharedfp=lockedfile
fem=$(dirname "$bin")/rollcheck-fem

# run_limited RANK LOG COMMAND...: the command on 2 ranks, rank RANK under the limit; its exit code.
# The write's patience (fem/field_output.h) 3 s, not 30: the rank held in
# HDF5's collective write is ended as soon.
run_limited() {
  local rank=$1 log=$2; shift 2
  ROLLCHECK_WRITE_PATIENCE=3 LIMITED_RANK=$rank timeout 240 mpirun -n 2 --oversubscribe -x LIMITED_RANK \
    -x ROLLCHECK_WRITE_PATIENCE sh -c \
    'if [ "$OMPI_COMM_WORLD_RANK" = "$LIMITED_RANK" ]; then trap "" XFSZ; ulimit -f 0; fi; exec "$@"' sh "$@" \
    > "$log" 2>&1
}

# failed CODE FILE LOG WHAT NAMED: exit 1, no hang, FILE named at least NAMED times (once per rank that says it).
failed() {
  local code=$1 file=$2 log=$3 what=$4 named=$5 before=$fail
  fail=0
  if [[ $code -eq 124 ]]; then
    echo "FAIL: $what: hung (killed after 240 s)"; fail=1
  else
    check '[[ $code -eq 1 ]]' "$what: exit $code, expected 1"
    check '[[ $(grep -c "error.*$file" "$log") -ge $named ]]' "$what: the file is not named by $named rank(s)"
    check '! grep -q "internal error" "$log"' "$what: an internal error"
  fi
  [[ $fail -eq 0 ]] || tail -n 20 "$log"
  ((fail |= before))
}

# Sanity: without the limit the same 2-rank run writes the pair.
run_limited none "$tmp/ok.log" "$fem" -q hertz --model axi --refine 0 --xdmf "$tmp/ok.xdmf"
check '[[ $? -eq 0 && -s $tmp/ok.xdmf && -s $tmp/ok.h5 ]]' "2 ranks without a limit: no field pair ($(tail -n 5 "$tmp/ok.log"))"

run_limited 1 "$tmp/xdmf.log" "$fem" hertz --model axi --refine 0 --xdmf "$tmp/f.xdmf"
# Rank 0 is held inside the HDF5 dataset write that failed on rank 1, so
# rank 1 names the file and ends both ranks (fem/first_failure.h).
failed $? "f\.xdmf" "$tmp/xdmf.log" "rank 1 cannot write its part of the fields" 1
check '[[ ! -e $tmp/f.xdmf && ! -e $tmp/f.h5 ]]' "a failed field write left f.xdmf or f.h5"
check '[[ -z $(ls -A "$tmp" | grep "^\.f\.tmp") ]]' "a failed field write left its temporary folder"

run_limited 0 "$tmp/json.log" "$fem" hertz --model axi --refine 0 --json "$tmp/summary.json"
failed $? "summary\.json" "$tmp/json.log" "rank 0 cannot write the summary" 2
check '[[ ! -e $tmp/summary.json ]]' "a failed summary write left summary.json"
exit $fail
