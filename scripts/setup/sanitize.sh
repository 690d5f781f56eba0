#!/usr/bin/env bash
# Builds rollcheck under AddressSanitizer and UBSan (the "asan" preset of
# CMakePresets.json: RelWithDebInfo in build-asan/) and runs the default suite
# there (`ctest -LE long`); arguments go to ctest (e.g. -R 'geometry|cli_').
# Any sanitizer report fails the run: UBSan does not recover, ASan halts at its
# first report, and every report is also written to build-asan/sanitizer-reports/
# and printed at the end, so a report from a child process (batch workers,
# mpirun ranks) fails the run even where its test expects a non-zero exit.
# detect_leaks=0: OpenMPI and PETSc keep what MPI_Init and PetscInitialize
# allocate until exit without freeing it, so LeakSanitizer would report at the
# end of every test that starts MPI; leaks of our own are not checked here.
# TARGETS="tests_geometry tests_io": build only those test executables (and what they
# link) and run only their tests, the light subset on a loaded machine.
# Usage: scripts/setup/sanitize.sh [ctest arguments...]   (JOBS=N: build/test jobs; TARGETS=...)
set -euo pipefail
here=$(cd "$(dirname "$0")/../.." && pwd)
build=$here/build-asan
jobs=${JOBS:-$(nproc)}
reports=$build/sanitizer-reports

# The options hold for the build too: test discovery runs the test executables.
rm -rf "$reports"
mkdir -p "$reports"
export ASAN_OPTIONS="detect_leaks=0:halt_on_error=1:strict_init_order=1:log_path=$reports/asan"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:log_path=$reports/ubsan"
export OPENBLAS_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

(cd "$here" && cmake --preset asan >/dev/null)
targets=(${TARGETS:-})
filter=()
if ((${#targets[@]})); then
  cmake --build "$build" -j "$jobs" --target "${targets[@]}"
  # Each test is labelled with its executable's name (cmake/test_labels.cmake).
  filter=(-L "^($(IFS='|'; echo "${targets[*]}"))\$")
else
  cmake --build "$build" -j "$jobs"
fi
status=0
ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE long "${filter[@]}" "$@" || status=$?
if compgen -G "$reports/*" >/dev/null; then
  for report in "$reports"/*; do
    echo "==== sanitizer report $report" >&2
    cat "$report" >&2
  done
  status=1
fi
exit "$status"
