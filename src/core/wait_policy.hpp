#pragma once
// How idle threads wait (issue 41). libgomp's threads, and Open MPI's ranks in MPI_Wait, spin while
// they wait for each other: the fastest on cores of their own, ruinous on a crowded host, where a
// spinning thread holds the core another needs (two 2-thread runs on 2 cores, or 2 ranks x 2
// threads there, each slowed 3-400x; bench/RESULTS.md). libgomp reads OMP_WAIT_POLICY once, when it
// is loaded, before main: so a crowded start re-executes the program with passive waits.
#include <string>

namespace trapdem {

// Called first in main(argc, argv). For a command that runs the engine (run, study, element,
// calibrate, showcase): when OMP_WAIT_POLICY is not set and the threads this process
// will use (--threads N in argv; without it every usable core) x its ranks on this host
// (OMPI_COMM_WORLD_LOCAL_SIZE) plus the other registered trapdem runs' threads exceed the host's
// cores, or its threads its own usable cores (HostLoad::oversubscribed, host_load.hpp), sets OMP_WAIT_POLICY=passive and OMPI_MCA_mpi_yield_when_idle=1 and
// re-executes the program with the same arguments (once). The process is registered in the
// host's run registry from here on (as "starting", until its run registers itself with its
// thread count), so that two runs started together see each other. Returns when it does not re-execute
// (not crowded, the policy set by hand, or the exec failed: the run then goes on as it was).
void wait_passively_when_crowded(int argc, char** argv);

// Whether wait_passively_when_crowded found the host crowded and its re-execution failed.
bool passive_restart_failed();

// OMP_WAIT_POLICY's value, "" when it is not set.
std::string wait_policy();

// This run's processes on this host: OMPI_COMM_WORLD_LOCAL_SIZE under Open MPI's mpirun, else 1.
int local_rank_count();

}  // namespace trapdem
