// A simulation on a domain decomposition (decomposition.hpp): attaching it, the sites it owns, the
// sums over the ranks, and the second half kick of the owned particles when it is not fused into
// the sweep. The step itself is the one of simulation.cpp, with the exchanges of halo.cpp.
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
  if (decomposition && !state_.bodies.empty())
    throw InputError("rigid bodies run on one process (a body's members would cross ranks); run without ranks");
  if (settings_.domain.periodic[0])
    throw InputError("domain: a periodic x axis is not supported across ranks (the slabs split x); make x bounded");
  decomposition_ = std::move(decomposition);
  if (decomposition_) {
    state_.lists.pairs = PairList{};
    state_.lists.walls = WallList{};
    state_.lists.pair_contact.clear();
    history_pending_ = false;
    decomposition_->adopt(state_.particles, settings_.domain);
    state_.ghosts = 0;
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
    const FrameSecondHalfKick in_frame{kick, state_.particles.position.data(), FrameKick(*frame_, time_, 0.5 * dt_)};
#pragma omp parallel for schedule(static) reduction(| : any_bad)
    for (std::size_t i = 0; i < n; ++i) any_bad |= in_frame(i);
    return any_bad;
  }
#pragma omp parallel for schedule(static) reduction(| : any_bad)
  for (std::size_t i = 0; i < n; ++i) any_bad |= kick(i);
  return any_bad;
}

}  // namespace trapdem
