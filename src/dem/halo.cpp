// The parts of Simulation::step (simulation.cpp) that cross a sub-domain boundary on a domain
// decomposition (decomposition.hpp), each doing only the one-process work without one. On ranks:
// 1. one reduction decides whether a particle escaped on some rank (stop before it would migrate
//    and its index change), whether any rank needs new lists (then every rank rebuilds:
//    rebuild_lists drops the ghosts, migrates particles with their histories, re-orders the owned
//    particles, exchanges ghosts and builds lists with each pair computed by one rank), or else the
//    ghosts' positions and velocities are updated from their owners;
// 2. after the contact sweep (without the fused kick: an owned particle's force is complete only
//    once the ghosts' shares come back) the ghosts' forces and torques go back to their owners and
//    the wall loads are summed;
// 3. the checks: each rank checks its own particles and contacts, one reduction tells whether any
//    failed and the largest overlap, and on a failure the ranks agree on the message.
// The halo's cost is counted in the stats (ghost_steps, exchange_seconds: the exchanges and
// reductions outside rebuilds, timed per call, never per particle).
#include <omp.h>

#include <exception>
#include <string>

#include "core/errors.hpp"
#include "dem/decomposition.hpp"
#include "dem/simulation.hpp"

namespace trapdem {

Simulation::NextLists Simulation::agree_on_next_lists() {
  // One reduction: whether a particle escaped or the lists are invalid on some rank, and the
  // displacements of all the ranks' particles (the box's lower corner negated: a max too).
  const DisplacementsSinceBuild& d = displacements_;
  double values[8] = {escaped_particle_ >= 0 ? 2.0 : (lists_valid_ ? 0.0 : 1.0),
                      d.max_length2, d.highest.x, d.highest.y, d.highest.z, -d.lowest.x, -d.lowest.y, -d.lowest.z};
  if (decomposition_) {
    const double asked = omp_get_wtime();
    decomposition_->max(values, 8);
    stats_.exchange_seconds += omp_get_wtime() - asked;
  }
  if (values[0] == 2.0) return NextLists::stop;
  if (values[0] == 1.0) return NextLists::rebuild;  // lists_valid_ is false on some rank: rebuilt on all
  const DisplacementsSinceBuild all{values[1], {-values[5], -values[6], -values[7]}, {values[2], values[3], values[4]}};
  return lists_outdated(all) ? NextLists::rebuild : NextLists::keep;
}

void Simulation::rebuild_lists_agreed() {
  if (!decomposition_) {
    rebuild_lists();
    return;
  }
  std::string failure;
  try {
    rebuild_lists();
  } catch (const std::exception& e) {
    failure = e.what();
  }
  decomposition_->agree_on_failure(failure);
}

void Simulation::update_ghosts() {
  if (!decomposition_) return;
  const double started = omp_get_wtime();
  decomposition_->update_ghosts(state_.particles);
  stats_.exchange_seconds += omp_get_wtime() - started;
}

void Simulation::forces(bool fused_kick) {
  const SecondHalfKick kick = second_half_kick();
  const ForcePassResult pass = backend_->compute_forces(state_, {settings_.domain, dt_, fused_kick ? &kick : nullptr});
  max_overlap_seen_ = pass.max_overlap_fraction;
  bad_particle_ = pass.kicked_not_finite ? first_non_finite_particle() : -1;
  if (!decomposition_) return;
  const double started = omp_get_wtime();
  decomposition_->return_ghost_forces(state_.particles);
  decomposition_->sum_wall_loads(state_.walls);
  stats_.exchange_seconds += omp_get_wtime() - started;
}

void Simulation::check_stability_agreed() {
  if (!decomposition_) {
    check_stability();
    return;
  }
  std::string failure;
  try {
    check_stability();
  } catch (const SimulationError& e) {
    failure = e.what();
  }
  double reduced[2] = {failure.empty() ? 0.0 : 1.0, max_overlap_seen_};
  const double started = omp_get_wtime();
  decomposition_->max(reduced, 2);
  stats_.exchange_seconds += omp_get_wtime() - started;
  if (reduced[0] > 0.0) decomposition_->agree_on_failure(failure);
  max_overlap_seen_ = reduced[1];
}

}  // namespace trapdem
