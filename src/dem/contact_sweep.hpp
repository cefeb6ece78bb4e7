#pragma once
// The engine's contact workspace (private to the engine: simulation.hpp only names it): the
// laws as the batch loops read them and each thread's batches and deferred shares. The sweep
// itself is Simulation::contacts (contact_sweep.cpp).
#include <vector>

#include "dem/contact/law.hpp"
#include "dem/pair_sweep.hpp"
#include "dem/wall_sweep.hpp"

namespace trapdem {

struct ContactSweep {
  LawParams particle_params;    // the particle law's
  LawChoices particle_choices;
  WallLaws wall_laws;           // per wall, fixed at add_wall

  // Per thread.
  std::vector<std::vector<PartnerShare>> deferred;  // shares for later threads' particles
  std::vector<ContactBatch> batches;
  std::vector<WallBatch> wall_batches;
  std::vector<Vec3> wall_loads;  // per thread and wall: force, torque
};

}  // namespace trapdem
