#pragma once
// The whole state of a decomposed run in one place: every rank's owned particles gathered, in
// id order (for output, checks and tests; the ghosts are left out).
#include <mpi.h>

#include "dem/particles.hpp"
#include "dem/simulation.hpp"

namespace trapdem {

// Collective: every rank receives all ranks' owned particles, sorted by id.
Particles gather_particles(const Simulation& sim, MPI_Comm comm);

}  // namespace trapdem
