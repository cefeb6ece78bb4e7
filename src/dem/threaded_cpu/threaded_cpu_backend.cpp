#include "dem/threaded_cpu/threaded_cpu_backend.hpp"

#include <omp.h>

#include <algorithm>

#include "dem/integrator.hpp"
#include "dem/pair_list.hpp"
#include "dem/thread_block.hpp"

namespace trapdem {

namespace {

// What every thread's sweep reads and writes, gathered once per step.
struct SweepInputs {
  Particles& p;
  const Domain& domain;
  bool periodic;
  double dt;
  PairSweepLists lists;
  PairHistoryRead history;             // last step's compact histories
  PairHistoryWrite next_history;       // this step's
  const std::uint32_t* first;          // the pair list's
  PairBatchLawFn pair_law;
  const LawParams& pair_params;
  const std::vector<Wall>& walls;
  WallList& wall_list;
  const WallLaws& wall_laws;
  const std::uint32_t* near_walls;     // the particles with walls within reach, ascending
  const std::uint32_t* near_walls_end;
  const std::uint32_t* partner_reach;  // per owner: one past the highest partner of those below
  const SecondHalfKick& second_half_kick;
  bool kick;
};

// One thread's sweep over its block of particles, contact-major: batch by batch, the touching
// pairs, the law over them, their shares; each particle's walls as soon as its pairs are all
// done; each particle's second half kick as soon as its force is complete.
class BlockSweep {
 public:
  BlockSweep(const SweepInputs& in, ThreadBlock block, ContactBatch& batch, WallBatch& wall_batch,
             std::vector<PartnerShare>& later, Vec3* wall_loads)
      : in_(in), block_(block), batch_(batch), wall_batch_(wall_batch), later_(later), wall_loads_(wall_loads) {}

  // Returns 1 when a kicked particle's state is not finite; raises max_overlap to the largest
  // overlap / smaller radius seen.
  int run(double& max_overlap) {
    max_overlap_ = max_overlap;
    start();
    sweep_pairs();
    finish();
    max_overlap = max_overlap_;
    return any_bad_;
  }

 private:
  // Empty shares, forces and batches; the cursors at the block's start.
  void start() {
    const auto [begin, end] = block_;
    later_.clear();
    for (std::size_t i = begin; i < end; ++i) {
      in_.p.force[i] = Vec3{};
      in_.p.torque[i] = Vec3{};
    }
    wall_batch_.count = 0;
    next_near_wall_ = std::lower_bound(in_.near_walls, in_.near_walls_end, std::uint32_t(begin));
    // The particles below the highest partner of the earlier blocks' owners get a share after
    // the sweep: they are kicked then (compute_forces).
    next_kick_ = in_.kick ? std::min(end, std::max<std::size_t>(begin, in_.partner_reach[begin])) : end;
  }

  // Batch by batch: the touching pairs, the law over them, their shares. The owner's shares are
  // summed and added once its last pair is done (a batch may end within an owner's pairs): the
  // same order of additions as a loop over the pairs owner by owner.
  void sweep_pairs() {
    const auto [begin, end] = block_;
    Particles& p = in_.p;
    const SweepPrefetch ahead_of{p.velocity.data(), p.angular_velocity.data(), p.force.data(),
                                 p.torque.data(),   in_.history,             in_.next_history};
    const BodyArrays bodies{p.radius.data(), p.mass.data(), p.inv_inertia.data(), p.velocity.data(),
                            p.angular_velocity.data()};
    PairCursor at{begin, 0};
    std::uint32_t next_contact = in_.first[begin];  // this block's part of next_history
    sums_ = {begin, Vec3{}, Vec3{}};
    while (at.owner < end) {
      const std::uint32_t count = collect_touching(at, end, p.position.data(), p.radius.data(), in_.lists, next_contact,
                                                   in_.domain, in_.periodic, batch_, ahead_of, p.size());
      in_.pair_law(batch_, count, in_.pair_params, bodies, in_.history, in_.dt);
      add_batch_shares(batch_, count, end, p.force.data(), p.torque.data(), in_.next_history, sums_, later_,
                       max_overlap_);
      walls_before(sums_.owner);  // the particles before the current owner have all their pair shares
      kick_before(wall_batch_.count > 0 ? std::min<std::size_t>(sums_.owner, wall_batch_.particle[0]) : sums_.owner);
    }
  }

  // The last owner's sums, the remaining walls, the remaining kicks.
  void finish() {
    const auto [begin, end] = block_;
    if (begin < end) {
      in_.p.force[sums_.owner] += sums_.force;
      in_.p.torque[sums_.owner] += sums_.torque;
    }
    walls_before(end);
    run_wall_batch();
    kick_before(end);
  }

  // The wall contacts of the block's particles before `done` (all their pair shares are in).
  void walls_before(std::size_t done) {
    for (; next_near_wall_ != in_.near_walls_end && *next_near_wall_ < done; ++next_near_wall_) {
      const std::uint32_t i = *next_near_wall_;
      if (wall_batch_.count + (in_.wall_list.first[i + 1] - in_.wall_list.first[i]) > WallBatch::kCapacity)
        run_wall_batch();
      collect_wall_contacts(i, in_.p, in_.walls, in_.wall_list, wall_batch_);
    }
  }

  void run_wall_batch() {
    wall_forces(wall_batch_, in_.wall_laws, in_.p, in_.wall_list, in_.dt, wall_loads_, max_overlap_);
  }

  // The second half kick of the particles before `limit` (their forces are complete).
  void kick_before(std::size_t limit) {
    for (; next_kick_ < limit; ++next_kick_) any_bad_ |= in_.second_half_kick(next_kick_);
  }

  const SweepInputs& in_;
  const ThreadBlock block_;
  ContactBatch& batch_;
  WallBatch& wall_batch_;
  std::vector<PartnerShare>& later_;
  Vec3* wall_loads_;
  const std::uint32_t* next_near_wall_ = nullptr;
  std::size_t next_kick_ = 0;
  OwnerSums sums_{};
  double max_overlap_ = 0.0;
  int any_bad_ = 0;
};

}  // namespace

// The pair kernel over the half list, contact-major. Particles are in cell order and each
// thread owns a contiguous block of them. A first loop walks the block's listed pairs, tests
// touching and appends the touching ones to a batch without a branch (about a third of the
// listed pairs touch, at random: a branch on it mispredicts). Each full batch then runs the
// contact law as one loop over its contacts that the compiler vectorises (the law's branches
// become selects), and a last, scalar loop stores the histories and adds the forces in pair order.
// A pair's owner (first body) is in the thread's block and its partner (second body, higher
// index) usually is too: then both shares are added at once. A partner in a later thread's block
// receives its share after the loop, from a per-thread list, in thread order. The sums are
// therefore the same every time for a given thread count; another thread count changes only the
// order of a few additions (round-off).
// The wall contacts of the block's particles are found in the same sweep, as soon as a particle's
// pairs are all done (its data is still in cache then; a pass of its own re-read it from memory at
// 80k particles), and run through the law in batches of their own. Each thread sums its own wall
// loads; the threads' sums are added in thread order. With `kick`, each particle also gets the
// second half kick of the step as soon as its force is complete.
ForcePassResult ThreadedCpuBackend::compute_forces(EngineState& state, const ForcePass& pass) {
  Particles& p = state.particles;
  ContactLists& lists = state.lists;
  const std::size_t n = p.size();
  const int threads = omp_get_max_threads();
  deferred_.resize(std::size_t(threads));
  batches_.resize(std::size_t(threads));
  wall_batches_.resize(std::size_t(threads));
  const std::size_t n_walls = state.walls.size();
  wall_loads_.assign(std::size_t(threads) * n_walls * 2, Vec3{});  // force, torque per thread and wall
  const bool kick = pass.second_half_kick != nullptr;
  const SecondHalfKick no_kick{};
  const SweepInputs in{p,
                       pass.domain,
                       pass.domain.any_periodic(),
                       pass.dt,
                       {lists.pairs.first.data(), lists.pairs.partner.data(), lists.pair_contact.data(),
                        static_cast<std::uint32_t>(lists.pairs.size())},
                       lists.contacts.read(),
                       lists.contacts_next.write(),
                       lists.pairs.first.data(),
                       pair_batch_law(particle_choices_),
                       particle_params_,
                       state.walls,
                       lists.walls,
                       wall_laws_,
                       lists.particles_near_walls.data(),
                       lists.particles_near_walls.data() + lists.particles_near_walls.size(),
                       lists.partner_reach.data(),
                       kick ? *pass.second_half_kick : no_kick,
                       kick};
  double max_overlap = 0.0;
  int any_bad = 0;
#pragma omp parallel reduction(max : max_overlap) reduction(| : any_bad)
  {
    const int me = omp_get_thread_num();
    BlockSweep sweep(in, thread_block(n, me, omp_get_num_threads()), batches_[std::size_t(me)],
                     wall_batches_[std::size_t(me)], deferred_[std::size_t(me)],
                     wall_loads_.data() + std::size_t(me) * n_walls * 2);
    any_bad |= sweep.run(max_overlap);
  }
  add_deferred_shares(p);
  if (kick) any_bad |= kick_after_deferred_shares(state, *pass.second_half_kick, threads);
  lists.contacts.swap(lists.contacts_next);
  sum_wall_loads(state.walls, threads);
  return {max_overlap, any_bad != 0};
}

void ThreadedCpuBackend::set_particle_law(const LawParams& params, const LawChoices& choices) {
  particle_params_ = params;
  particle_choices_ = choices;
}

void ThreadedCpuBackend::add_wall_law(const LawParams& params, const LawChoices& choices) { wall_laws_.add(params, choices); }

// The shares for partners in later threads' blocks, in thread order.
void ThreadedCpuBackend::add_deferred_shares(Particles& p) const {
  for (const auto& shares : deferred_) {
    for (const PartnerShare& s : shares) {
      p.force[s.particle] += s.force;
      p.torque[s.particle] += s.torque;
    }
  }
}

// The particles that received a share after the sweep, block by block: each block's particles
// below the highest partner of the earlier blocks' owners (ContactLists::partner_reach).
int ThreadedCpuBackend::kick_after_deferred_shares(const EngineState& state, const SecondHalfKick& second_half_kick,
                                                   int threads) const {
  int any_bad = 0;
  for (int th = 0; th < threads; ++th) {
    const auto [begin, end] = thread_block(state.particles.size(), th, threads);
    const std::size_t reach = std::min(end, std::max<std::size_t>(begin, state.lists.partner_reach[begin]));
    for (std::size_t p = begin; p < reach; ++p) any_bad |= second_half_kick(p);
  }
  return any_bad;
}

// The walls' loads: each thread's sums, in thread order.
void ThreadedCpuBackend::sum_wall_loads(std::vector<Wall>& walls, int threads) const {
  const std::size_t n_walls = walls.size();
  for (std::size_t k = 0; k < n_walls; ++k) {
    walls[k].force = Vec3{};
    walls[k].torque = Vec3{};
    for (int th = 0; th < threads; ++th) {
      walls[k].force += wall_loads_[(std::size_t(th) * n_walls + k) * 2];
      walls[k].torque += wall_loads_[(std::size_t(th) * n_walls + k) * 2 + 1];
    }
  }
}

std::unique_ptr<ForceBackend> make_threaded_cpu_backend() { return std::make_unique<ThreadedCpuBackend>(); }

}  // namespace trapdem
