#pragma once
// The whole state of a decomposed run in one place: every rank's owned particles gathered, in
// id order (for output, checks and tests; the ghosts are left out).
#include <mpi.h>

#include "dem/particles.hpp"
#include "dem/simulation.hpp"

namespace trapdem {

// Collective: every rank receives all ranks' owned particles, sorted by id.
Particles gather_particles(const Simulation& sim, MPI_Comm comm);
// Collective: rank 0 receives all ranks' owned particles, sorted by id (output); the others an
// empty set.
Particles gather_particles_on_root(const Simulation& sim, MPI_Comm comm);

// Collective: every rank's bytes, rank after rank, on rank 0 (each rank's length in `lengths`
// there); the others receive nothing.
std::vector<char> gather_bytes_on_root(const std::vector<char>& mine, MPI_Comm comm, std::vector<std::size_t>* lengths = nullptr);

}  // namespace trapdem
