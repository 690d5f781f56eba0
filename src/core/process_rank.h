#pragma once
// The process that speaks: under MPI only rank 0 of MPI_COMM_WORLD prints
// summaries, writes outputs and logs progress. One query for every caller
// (the executables, the study layer's progress beats).
//
// Contract: this process's rank in MPI_COMM_WORLD; 0 where MPI is not
// initialised (a serial run, the fast executable, which starts no MPI) or
// already finalised. Never initialises MPI.

namespace rollcheck
{
int process_rank();
} // namespace rollcheck
