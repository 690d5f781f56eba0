#pragma once
// How this process was started, for the code that starts MPI in it.
//
// A process that no launcher (mpirun, mpiexec, srun) started is an MPI
// "singleton" when it initialises MPI. Open MPI 4 then forks and execs a
// supporting daemon (orted) unless the MCA parameter ess_singleton_isolated
// is set; rollcheck never spawns processes through MPI (MPI_Comm_spawn), so
// it asks for the isolated singleton and saves the daemon's start
// (scripts/bench/bench_startup.sh measures both).
// Reference: Open MPI 4.1 `ompi_info --all`, component ess singleton.

namespace rollcheck
{
/// Whether an MPI launcher started this process (its environment names the
/// process's rank: Open MPI, PMIx or PMI).
bool launched_by_mpi();

/// To be called before MPI starts: in a process no launcher started, sets
/// OMPI_MCA_ess_singleton_isolated=1 unless the environment already sets it
/// (a user's choice wins). Children inherit it; a launcher ignores it.
void prefer_isolated_mpi_singleton();
} // namespace rollcheck
