// The step of one rank of a domain decomposition (decomposition.hpp): the single-process step's
// parts in the same order, with the exchanges between them. The contact sweep, the law, the lists
// and the integrator are the engine's own; only what crosses a sub-domain boundary is added.
//
// 1. first half kick and drift of the owned particles (integrator.cpp);
// 2. a stop on every rank when a particle escaped on one (before it would migrate); a list
//    rebuild on every rank when any rank needs one (rebuild_lists: ghosts dropped, particles
//    migrated with their histories, owned particles re-ordered, ghosts exchanged, lists built with
//    each pair computed by one rank, keep_pairs_computed_here); else the ghosts' positions and
//    velocities updated from their owners;
// 3. the contact sweep (contact_sweep.cpp) without the fused kick: an owned particle's force is
//    complete only once the ghosts' shares come back from the other ranks;
// 4. the ghosts' forces and torques returned to their owners, then the second half kick;
// 5. the wall loads and the largest overlap reduced over the ranks, the checks agreed on.
// The halo's cost is counted in the stats (ghost_steps, exchange_seconds: the exchanges and
// reductions of steps 2-5 outside rebuilds, timed per call, never per particle).
#include <omp.h>

#include <string>

#include "core/errors.hpp"
#include "dem/decomposition.hpp"
#include "dem/integrator.hpp"
#include "dem/simulation.hpp"

namespace trapdem {

void Simulation::set_decomposition(std::unique_ptr<Decomposition> decomposition) {
  if (setup_done_)
    throw InputError("a decomposition is attached before the first step (every rank from the same initial state)");
  if (settings_.domain.periodic[0])
    throw InputError("domain: a periodic x axis is not supported across ranks (the slabs split x); make x bounded");
  decomposition_ = std::move(decomposition);
  if (decomposition_) {
    pairs_ = PairList{};
    wall_list_ = WallList{};
    pair_contact_.clear();
    history_pending_ = false;
    decomposition_->adopt(p_, settings_.domain);
    ghosts_ = 0;
    invalidate_lists();
  }
}

bool Simulation::owns_site(const Vec3& x) const { return !decomposition_ || decomposition_->owns(x); }

double Simulation::global_sum(double local) const { return decomposition_ ? decomposition_->sum(local) : local; }

int Simulation::kick_owned() {
  const SecondHalfKick kick = second_half_kick();
  const std::size_t n = owned_count();
  int any_bad = 0;
  if (frame_) {  // a loop of its own: the uniform-gravity loop below stays as it was
    const FrameSecondHalfKick in_frame{kick, p_.position.data(), FrameKick(*frame_, time_, 0.5 * dt_)};
#pragma omp parallel for schedule(static) reduction(| : any_bad)
    for (std::size_t i = 0; i < n; ++i) any_bad |= in_frame(i);
    return any_bad;
  }
#pragma omp parallel for schedule(static) reduction(| : any_bad)
  for (std::size_t i = 0; i < n; ++i) any_bad |= kick(i);
  return any_bad;
}

void Simulation::step_decomposed() {
  Decomposition& d = *decomposition_;
  // A failure on one rank (a list that cannot be built) is agreed on before the next exchange.
  auto rebuild_agreed = [&] {
    std::string failure;
    try {
      rebuild_lists();
    } catch (const std::exception& e) {
      failure = e.what();
    }
    d.agree_on_failure(failure);
  };
  auto fail_together = [&] {  // each rank checks its own, then all throw the first failure, or none
    std::string failure;
    try {
      check_stability();
    } catch (const SimulationError& e) {
      failure = e.what();
    }
    d.agree_on_failure(failure);
  };
  auto forces = [&] {
    contacts(false);
    const double started = omp_get_wtime();
    d.return_ghost_forces(p_);
    d.sum_wall_loads(walls_);
    stats_.exchange_seconds += omp_get_wtime() - started;
  };
  if (!setup_done_) {  // forces of the initial state, so the first half kick sees them
    rebuild_agreed();
    forces();
    setup_done_ = true;
  }
  integrate_positions();
  // One reduction decides: 2, a particle escaped on some rank (stop before it would migrate and
  // its index change); 1, a rank needs new lists; 0, the ghosts are updated.
  const double asked = omp_get_wtime();
  const double next = d.max(escaped_particle_ >= 0 ? 2.0 : (lists_outdated() ? 1.0 : 0.0));
  stats_.exchange_seconds += omp_get_wtime() - asked;
  if (next == 2.0) fail_together();
  if (next == 1.0) {
    rebuild_agreed();
  } else {
    const double started = omp_get_wtime();
    d.update_ghosts(p_);
    stats_.exchange_seconds += omp_get_wtime() - started;
  }
  forces();
  stats_.ghost_steps += std::int64_t(ghosts_);
  bad_particle_ = kick_owned() ? first_non_finite_particle() : -1;
  ++stats_.steps;
  // Each rank checks its own particles and contacts (the message names the one it found); one
  // reduction tells whether any failed and the largest overlap; on a failure the ranks agree on
  // the message.
  std::string failure;
  try {
    check_stability();
  } catch (const SimulationError& e) {
    failure = e.what();
  }
  double reduced[2] = {failure.empty() ? 0.0 : 1.0, max_overlap_seen_};
  const double started = omp_get_wtime();
  d.max(reduced, 2);
  stats_.exchange_seconds += omp_get_wtime() - started;
  if (reduced[0] > 0.0) d.agree_on_failure(failure);
  max_overlap_seen_ = reduced[1];
}

}  // namespace trapdem
