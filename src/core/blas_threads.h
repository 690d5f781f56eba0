#pragma once
// One BLAS thread per process, unless the user chose a number.
//
// rollcheck's parallelism is its MPI ranks and its worker processes. The
// BLAS behind PETSc on Debian is OpenBLAS's pthreads build, which runs each
// call on one thread per CPU and then keeps its threads spinning on
// sched_yield for the next call: beside another rank or process on the same
// cores they take that one's CPU, for none of rollcheck's small dense
// kernels (MUMPS's fronts) gains from them, and the thread count moves the
// last bits of a result. (scripts/bench/bench_blas_threads.sh measures it.)
// OpenBLAS reads OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS or OMP_NUM_THREADS
// when it loads; where none is set, this asks it for one thread through
// openblas_set_num_threads (OpenBLAS's cblas.h), found at run time, so that
// another BLAS is left as it is.

namespace rollcheck
{
/// Where OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS and OMP_NUM_THREADS are all
/// unset and the process's BLAS is OpenBLAS's pthreads build
/// (openblas_get_parallel() == 1; its OpenMP build would set OpenMP's count
/// for the whole process), sets its threads to one. Returns whether it did.
bool prefer_one_blas_thread();
} // namespace rollcheck
