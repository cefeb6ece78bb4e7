#pragma once
// `trapdem run` on the ranks an MPI launcher started (mpirun -n R trapdem run CONFIG): every
// rank runs the same run_in_folder with MpiRunRanks over MPI_COMM_WORLD.
#include "experiment/folder_run.hpp"

namespace trapdem {

// Initialises MPI (unless the caller did), runs the experiment on every rank, finalises MPI.
// Returns as run_in_folder's caller would: 0 finished, 130 stopped with a checkpoint. An error
// agreed on by every rank is thrown on rank 0 (the caller prints it) and returned quietly as its
// exit code on the others (2 input, 3 simulation, 4 file, 1 other, as the command's main);
// an error seen by one rank alone aborts every rank (MPI_Abort) after printing it, so that none
// waits for ever in an exchange.
int run_in_folder_on_ranks(FolderRunOptions options);

}  // namespace trapdem
