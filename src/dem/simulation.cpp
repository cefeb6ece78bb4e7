#include "dem/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

#include <fmt/format.h>

#include "dem/contact_kernel.hpp"
#include "core/errors.hpp"

namespace trapdem {

namespace {
constexpr std::int64_t kNone = std::numeric_limits<std::int64_t>::max();
}

Simulation::Simulation(Particles particles, const ContactLaw& particle_law, SimulationSettings settings)
    : p_(std::move(particles)), law_(particle_law), settings_(settings) {
  law_.validate("particle contact law");
  constants_ = make_constants(law_);
  set_gravity(Vec3{0.0, 0.0, -9.81});
  for (int a = 0; a < 3; ++a) {
    if (!(settings_.domain.upper[a] > settings_.domain.lower[a]))
      throw InputError(fmt::format("domain: upper bound must exceed lower bound on axis {} (got {} .. {})", "xyz"[a],
                                   settings_.domain.lower[a], settings_.domain.upper[a]));
  }
  if (settings_.skin > 0.0) {
    skin_ = settings_.skin;
  } else if (!p_.empty()) {
    skin_ = 0.2 * 2.0 * std::accumulate(p_.radius.begin(), p_.radius.end(), 0.0) / double(p_.size());
  } else {
    throw InputError("simulation: the Verlet skin cannot be derived without particles; set settings.skin (m)");
  }
  if (settings_.time_step > 0.0) {
    dt_ = settings_.time_step;
  } else if (!p_.empty()) {
    dt_ = settings_.time_step_fraction * critical_time_step();
  } else {
    throw InputError("simulation: the time step cannot be derived without particles; set settings.time_step (s)");
  }
}

void Simulation::set_gravity(const Vec3& g) {
  constant_gravity_ = g;
  gravity_is_constant_ = true;
  gravity_ = nullptr;
}

void Simulation::set_gravity(std::function<Vec3(double)> g) {
  gravity_ = std::move(g);
  gravity_is_constant_ = false;
}

Vec3 Simulation::gravity() const { return gravity_is_constant_ ? constant_gravity_ : gravity_(time_); }

std::size_t Simulation::add_wall(Wall wall) {
  wall.law.validate("wall '" + wall.name + "'");
  wall_laws_.add(make_constants(wall.law));
  walls_.push_back(std::move(wall));
  invalidate_lists();
  return walls_.size() - 1;
}

std::size_t Simulation::find_wall(const std::string& name) const {
  for (std::size_t k = 0; k < walls_.size(); ++k)
    if (walls_[k].name == name) return k;
  throw InputError(fmt::format("no wall named '{}'", name));
}

void Simulation::add_particle(std::int64_t id, const Vec3& x, double radius, double density, const Vec3& v) {
  if (!(radius > 0.0) || !(density > 0.0))
    throw InputError(fmt::format("particle {}: radius ({} m) and density ({} kg/m3) must be positive", id, radius, density));
  p_.add(id, x, radius, density, v);  // appending keeps the existing indices: the lists' history stays valid
  invalidate_lists();
}

void Simulation::remove_particles(const std::vector<std::uint32_t>& indices) {
  if (indices.empty()) return;
  if (!history_pending_ && !pairs_.first.empty()) {
    pending_history_.store_pairs(pairs_, pair_contact_, contacts_.data(), p_.id);
    pending_history_.store_walls(wall_list_, p_.id);
    history_pending_ = true;
  }
  std::vector<char> drop(p_.size(), 0);
  for (auto i : indices) drop.at(i) = 1;
  std::vector<std::uint32_t> keep;
  for (std::uint32_t i = 0; i < p_.size(); ++i)
    if (!drop[i]) keep.push_back(i);
  p_.permute(keep);
  invalidate_lists();
}

double Simulation::critical_time_step() const {
  if (p_.empty()) return std::numeric_limits<double>::infinity();
  const double m_min = *std::min_element(p_.mass.begin(), p_.mass.end());
  double k_max = law_.normal_stiffness;
  for (const Wall& w : walls_) k_max = std::max(k_max, w.law.normal_stiffness);
  return std::sqrt(m_min / k_max);
}

void Simulation::run(std::int64_t steps) {
  for (std::int64_t s = 0; s < steps; ++s) step();
}

// One time step: velocity Verlet as LAMMPS's nve/sphere does it (half kick, drift, forces at the
// new positions with the half-step velocities, half kick). Second order in dt for conservative
// forces; the dashpot sees velocities half a step old, which is first order and standard in DEM.
void Simulation::step() {
  if (!setup_done_) {  // forces of the initial state, so the first half kick sees them
    rebuild_lists();
    contacts(false);
    setup_done_ = true;
  }
  integrate_positions();
  update_neighbours_if_needed();
  contacts(true);  // with the second half kick
  ++stats_.steps;
  check_stability();
}

void Simulation::find_particles_near_walls() {
  particles_near_walls_.clear();
  for (std::uint32_t i = 0; i + 1 < wall_list_.first.size(); ++i)
    if (wall_list_.first[i + 1] > wall_list_.first[i]) particles_near_walls_.push_back(i);
}

// partner_reach_[i]: one past the highest partner of the owners below i (0 when none), for the
// second half kick in the sweep (Simulation::contacts).
void Simulation::find_partner_reach() {
  const std::size_t n = pairs_.first.empty() ? 0 : pairs_.first.size() - 1;
  partner_reach_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t highest =
        pairs_.first[i + 1] > pairs_.first[i] ? pairs_.partner[pairs_.first[i + 1] - 1] + 1 : 0;
    partner_reach_[i + 1] = std::max(partner_reach_[i], highest);
  }
}

// Room for a history per listed pair in both arrays (a thread's block writes from index
// first[begin] on, and every listed pair may touch). Grown only: the pages of a larger earlier
// list stay, and nothing is written but the empty entry at index pairs_.size(), where a contact
// that has just formed reads its history from.
void Simulation::size_contact_arrays() {
  const std::size_t needed = pairs_.size() + 1;
  if (contacts_.size() < needed) {
    contacts_.resize(needed);
    contacts_next_.resize(needed);
  }
  contacts_[pairs_.size()] = ContactHistory{};
  contacts_next_[pairs_.size()] = ContactHistory{};
}

// The per-listed-pair history of a checkpoint into the compact form.
void Simulation::compact_pair_history() {
  size_contact_arrays();
  pair_contact_.assign(pairs_.size(), kNoContact);
  std::uint32_t found = 0;
  for (std::size_t k = 0; k < pairs_.history.size(); ++k) {
    if (!pairs_.history[k].touching()) continue;
    contacts_[found] = pairs_.history[k];
    pair_contact_[k] = found++;
  }
  pairs_.history.clear();
  pairs_.history.shrink_to_fit();
}

std::vector<ContactHistory> Simulation::pair_history() const {
  std::vector<ContactHistory> history(pairs_.size());
  for (std::size_t k = 0; k < pair_contact_.size(); ++k)
    if (pair_contact_[k] != kNoContact) history[k] = contacts_[pair_contact_[k]];
  return history;
}

PairList Simulation::pairs() const {
  PairList copy{pairs_.first, pairs_.partner, pair_history()};
  return copy;
}

void Simulation::integrate_positions() {
  const double dt = dt_, half = 0.5 * dt_;
  const Vec3 g = gravity();
  // Bounds of the escape check: none on periodic axes.
  const Domain& dom = settings_.domain;
  Vec3 lo = dom.lower, hi = dom.upper;
  for (int a = 0; a < 3; ++a) {
    if (dom.periodic[a]) {
      lo[a] = -std::numeric_limits<double>::infinity();
      hi[a] = std::numeric_limits<double>::infinity();
    }
  }
  const bool rotate = !settings_.freeze_rotation;
  const std::size_t n = p_.size();
  Vec3* x = p_.position.data();
  Vec3* v = p_.velocity.data();
  Vec3* w = p_.angular_velocity.data();
  const Vec3* f = p_.force.data();
  const Vec3* t = p_.torque.data();
  const double* inv_m = p_.inv_mass.data();
  const double* inv_i = p_.inv_inertia.data();
  // Particles added since the last build have no reference position: the lists are invalid then
  // and will be rebuilt anyway.
  const bool track = lists_valid_ && position_at_build_.size() == n;
  const Vec3* x0 = position_at_build_.data();
  // Whether any particle left is a flag here (a reduction the loop vectorises with); which one,
  // only when one did.
  double max_d2 = 0.0;
  int outside = 0;
#pragma omp parallel for simd schedule(static) reduction(max : max_d2) reduction(| : outside)
  for (std::size_t i = 0; i < n; ++i) {
    v[i] += half * (f[i] * inv_m[i] + g);
    x[i] += dt * v[i];
    if (rotate) w[i] += (half * inv_i[i]) * t[i];
    if (track) max_d2 = std::max(max_d2, norm2(x[i] - x0[i]));
    const bool inside = x[i].x >= lo.x && x[i].x <= hi.x && x[i].y >= lo.y && x[i].y <= hi.y && x[i].z >= lo.z &&
                        x[i].z <= hi.z;  // false for NaN too
    outside |= inside ? 0 : 1;
  }
  max_displacement2_ = max_d2;
  escaped_particle_ = -1;
  for (std::size_t i = 0; outside && i < n; ++i) {
    const bool inside = x[i].x >= lo.x && x[i].x <= hi.x && x[i].y >= lo.y && x[i].y <= hi.y && x[i].z >= lo.z &&
                        x[i].z <= hi.z;
    if (!inside) {
      escaped_particle_ = std::int64_t(i);
      break;
    }
  }

  for (Wall& wall : walls_) {
    wall.current_velocity = wall.velocity ? wall.velocity(time_ + half) : Vec3{};
    wall.origin += dt * wall.current_velocity;
    wall.displacement += dt * wall.current_velocity;
  }
  time_ += dt;
}

void Simulation::update_neighbours_if_needed() {
  const double limit = 0.5 * skin_;
  bool rebuild = !lists_valid_ || max_displacement2_ > limit * limit;
  for (std::size_t k = 0; k < walls_.size() && !rebuild; ++k)
    rebuild = norm2(walls_[k].displacement - wall_displacement_at_build_[k]) > limit * limit;
  if (rebuild) rebuild_lists();
}

void Simulation::rebuild_lists() {
  const double started = omp_get_wtime();
  ++stats_.rebuilds;
  // Wrap periodic axes into the domain, counting the images crossed.
  const Domain& dom = settings_.domain;
  if (dom.any_periodic()) {
    for (std::size_t i = 0; i < p_.size(); ++i) {
      for (int a = 0; a < 3; ++a) {
        if (!dom.periodic[a]) continue;
        const double len = dom.length(a);
        double& xa = p_.position[i][a];
        const double shift = std::floor((xa - dom.lower[a]) / len);
        if (shift != 0.0) {
          xa -= shift * len;
          if (xa >= dom.upper[a]) xa = dom.lower[a];  // round-off at the upper bound
          p_.image[i][a] += static_cast<std::int32_t>(shift);
        }
      }
    }
  }
  HistoryArchive archive;
  if (history_pending_) {
    archive = std::move(pending_history_);
    history_pending_ = false;
  } else {
    archive.store_pairs(pairs_, pair_contact_, contacts_.data(), p_.id);
    archive.store_walls(wall_list_, p_.id);
  }

  const double r_max = p_.empty() ? 0.0 : *std::max_element(p_.radius.begin(), p_.radius.end());
  const double cell = 2.0 * r_max + skin_;
  for (int a = 0; a < 3; ++a) {
    if (dom.periodic[a] && dom.length(a) < 2.0 * cell)
      throw InputError(fmt::format(
          "periodic axis {}: the domain length {} m must be at least twice the interaction range {} m", "xyz"[a],
          dom.length(a), cell));
  }
  CellSort cells = sort_into_cells(p_.position, dom, cell);
  const bool reorder = settings_.reorder_every > 0 && rebuilds_since_reorder_ % settings_.reorder_every == 0;
  ++rebuilds_since_reorder_;
  if (reorder) {
    p_.permute(cells.order);
    cells = sort_into_cells(p_.position, dom, cell);
  }
  build_pairs(p_, cells, dom, skin_, pairs_);
  size_contact_arrays();
  archive.restore_pairs(pairs_, p_.id, pair_contact_, contacts_.data());
  build_wall_candidates(p_, walls_, skin_, wall_list_);
  archive.restore_walls(wall_list_, p_.id);

  find_particles_near_walls();
  find_partner_reach();
  position_at_build_ = p_.position;
  wall_displacement_at_build_.resize(walls_.size());
  for (std::size_t k = 0; k < walls_.size(); ++k) wall_displacement_at_build_[k] = walls_[k].displacement;
  lists_valid_ = true;
  stats_.rebuild_seconds += omp_get_wtime() - started;
}

namespace {
// The contact law over a batch of touching pairs: one loop over the contacts with no branch the
// compiler cannot turn into selects, so that it runs several contacts per instruction (8 with
// AVX-512). The law's choices (rolling model, lever arm, rolling stiffness and dashpot) are
// template arguments, resolved at compile time: GCC neither if-converts a loop-invariant
// three-way branch nor vectorises a select on a loop-invariant flag.
struct PairBatchLaw {
  using Fn = void (*)(ContactBatch&, std::uint32_t, ContactConstants, const double*, const double*, const double*,
                      const Vec3*, const Vec3*, const ContactHistory*, double);
  template <int kRolling, bool kEffectiveLever, bool kRollingStiffnessFromKt, bool kRollingDashpot>
  static void run(ContactBatch& batch, std::uint32_t count, ContactConstants c, const double* __restrict r,
                  const double* __restrict m, const double* __restrict inv_i, const Vec3* __restrict v,
                  const Vec3* __restrict w, const ContactHistory* __restrict history, double dt);
};

template <int kRolling, bool kEffectiveLever, bool kRollingStiffnessFromKt, bool kRollingDashpot>
void PairBatchLaw::run(ContactBatch& batch, std::uint32_t count, ContactConstants c, const double* __restrict r,
                       const double* __restrict m, const double* __restrict inv_i, const Vec3* __restrict v,
                       const Vec3* __restrict w, const ContactHistory* __restrict history, double dt) {
  c.rolling = kRolling;
  c.effective_lever_arm = kEffectiveLever;
  c.rolling_stiffness_from_kt = kRollingStiffnessFromKt;
  c.needs_rolling_inertia = kRollingDashpot;
  c.needs_spin_inertia = kRolling == 1;
  // The batch's output arrays never overlap what the loop reads.
#pragma GCC ivdep
  for (std::uint32_t q = 0; q < count; ++q) {
    const std::uint32_t i = batch.owner[q], j = batch.partner[q];
    const Vec3 d{batch.separation[0][q], batch.separation[1][q], batch.separation[2][q]};
    const double ri = r[i], rj = r[j];
    const double reach = ri + rj;
    const double dist = std::sqrt(norm2(d));
    const Vec3 normal = d * (1.0 / dist);
    const double overlap = reach - dist;
    batch.overlap_ratio[q] = overlap / std::min(ri, rj);
    const double mi = m[i], mj = m[j];
    ContactBodies b;
    b.effective_mass = mi * mj / (mi + mj);
    b.arm_i = ri - 0.5 * overlap;
    b.arm_j = rj - 0.5 * overlap;
    b.lever = c.effective_lever_arm ? ri * rj / reach : 0.5 * reach;
    // Loaded unconditionally: a load under a branch would keep the loop from vectorising.
    const double inv_ii = inv_i[i], inv_ij = inv_i[j];
    b.rolling_inertia = c.needs_rolling_inertia
                            ? 1.0 / (1.0 / (1.0 / inv_ii + mi * ri * ri) + 1.0 / (1.0 / inv_ij + mj * rj * rj))
                            : 0.0;
    b.spin_inertia = c.needs_spin_inertia ? 1.0 / (inv_ii + inv_ij) : 0.0;
    ContactHistory h = history[batch.history_in[q]];
    const ContactForce cf = contact_force(c, b, normal, overlap, v[i] - v[j], w[i], w[j], h, dt);
    const Vec3 n_x_ft = cross(normal, cf.tangential);
    const Vec3 ti = cf.rolling_torque - b.arm_i * n_x_ft;
    const Vec3 tj = -cf.rolling_torque - b.arm_j * n_x_ft;
    store_in_lane(batch, q, cf.force, h);
    batch.torque_owner[0][q] = ti.x;
    batch.torque_owner[1][q] = ti.y;
    batch.torque_owner[2][q] = ti.z;
    batch.torque_partner[0][q] = tj.x;
    batch.torque_partner[1][q] = tj.y;
    batch.torque_partner[2][q] = tj.z;
  }
}

// Where collect_touching() stopped: the owner and its next listed pair.
struct PairCursor {
  std::size_t owner;
  std::uint32_t pair;
};

// Appends the touching pairs from `at` on to the empty batch until the batch is full or the
// owners up to `end` are done; returns how many it appended. Every listed pair is written to the
// batch and kept only when touching (no branch on touching, which is at random). A pair that
// stopped touching loses its history (its index becomes kNoContact); one that has just formed
// reads the empty entry `no_history`. `next_contact` is where the next contact's history goes. A
// function of its own, with no call inside, so that its few live values stay in registers.
// The sweep first touches a particle's data as the highest partner of an earlier owner, at no
// fixed stride from the owner: the hardware prefetcher does not see it coming, and beyond the last
// level cache (80k particles) every first touch waits for memory. So the data the law will read,
// and the force and torque the shares will add to, just past the owner's highest partner are
// prefetched. The contact histories are read through the batch law's gathers and written in
// add_batch_shares, both about in pair order: without help, each of their cache lines beyond the
// last level cache was a wait for memory (the 80k benchmark ran ~30 % slower per particle than the
// 20k one). They are prefetched kHistoryAhead contacts ahead of the one being collected.
struct SweepPrefetch {
  const Vec3* velocity;
  const Vec3* angular_velocity;
  const Vec3* force;
  const Vec3* torque;
  const ContactHistory* history;     // last step's, read by the batch law
  const ContactHistory* next_history;  // this step's, written by add_batch_shares
};
constexpr std::uint32_t kHistoryAhead = 24;  // contacts; 24-48 measured alike at 80k, 96 less good

template <bool kPeriodic>
std::uint32_t collect_touching(PairCursor& at, std::size_t end, const Vec3* __restrict x, const double* __restrict r,
                               const std::uint32_t* __restrict first, const std::uint32_t* __restrict partner,
                               std::uint32_t* __restrict pair_contact, std::uint32_t no_history,
                               std::uint32_t& next_contact, const Domain& dom, ContactBatch& __restrict batch,
                               const SweepPrefetch& ahead_of, std::size_t n) {
  std::uint32_t next = next_contact;
  std::uint32_t count = 0;
  for (std::size_t i = at.owner; i < end; ++i) {
    const Vec3 xi = x[i];
    const double ri = r[i];
    const std::uint32_t last = first[i + 1];
    if (last > first[i]) {
      const std::size_t ahead = std::min<std::size_t>(partner[last - 1] + 8, n - 1);
      __builtin_prefetch(&x[ahead]);
      __builtin_prefetch(&ahead_of.velocity[ahead]);
      __builtin_prefetch(&ahead_of.angular_velocity[ahead]);
      __builtin_prefetch(&ahead_of.force[ahead], 1);
      __builtin_prefetch(&ahead_of.torque[ahead], 1);
    }
    for (std::uint32_t k = std::max(at.pair, first[i]); k < last; ++k) {
      const std::uint32_t j = partner[k];
      Vec3 d = xi - x[j];
      if constexpr (kPeriodic) d = dom.minimum_image(d);
      const double reach = ri + r[j];
      const bool touching = norm2(d) < reach * reach;
      const std::uint32_t last_step = pair_contact[k];
      pair_contact[k] = touching ? next : kNoContact;
      batch.owner[count] = std::uint32_t(i);
      batch.partner[count] = j;
      batch.history_in[count] = last_step == kNoContact ? no_history : last_step;
      batch.history_out[count] = next;
      batch.separation[0][count] = d.x;
      batch.separation[1][count] = d.y;
      batch.separation[2][count] = d.z;
      count += touching ? 1u : 0u;
      next += touching ? 1u : 0u;
      const std::uint32_t history_ahead = std::min(next + kHistoryAhead, no_history);
      __builtin_prefetch(&ahead_of.history[history_ahead]);
      __builtin_prefetch(&ahead_of.next_history[history_ahead], 1);
      if (count == ContactBatch::kCapacity) {
        at = {i, k + 1};
        next_contact = next;
        return count;
      }
    }
  }
  at = {end, 0};
  next_contact = next;
  return count;
}

// A thread's running sums for the owner whose pairs are being added (see Simulation::contacts).
struct OwnerSums {
  std::size_t owner;
  Vec3 force, torque;
};

// Stores the batch's histories and adds its forces and torques in pair order: the partner's share
// at once (or, for a partner at or beyond `end`, in `later`), the owner's summed until its last pair.
void add_batch_shares(const ContactBatch& __restrict batch, std::uint32_t count, std::size_t end, Vec3* __restrict f,
                      Vec3* __restrict t, ContactHistory* __restrict history, OwnerSums& sums,
                      std::vector<Simulation::PartnerShare>& later, double& max_overlap) {
  for (std::uint32_t q = 0; q < count; ++q) {
    const std::uint32_t i = batch.owner[q], j = batch.partner[q];
    if (i != sums.owner) {
      f[sums.owner] += sums.force;
      t[sums.owner] += sums.torque;
      sums = {i, Vec3{}, Vec3{}};
    }
    max_overlap = std::max(max_overlap, batch.overlap_ratio[q]);
    ContactHistory& h = history[batch.history_out[q]];
    h.tangential_spring = {batch.spring[0][q], batch.spring[1][q], batch.spring[2][q]};
    h.rolling_spring = {batch.rolling_spring[0][q], batch.rolling_spring[1][q], batch.rolling_spring[2][q]};
    h.flags = batch.flags[q];
    const Vec3 force{batch.force[0][q], batch.force[1][q], batch.force[2][q]};
    sums.force += force;
    sums.torque += Vec3{batch.torque_owner[0][q], batch.torque_owner[1][q], batch.torque_owner[2][q]};
    const Vec3 tj{batch.torque_partner[0][q], batch.torque_partner[1][q], batch.torque_partner[2][q]};
    if (j < end) {
      f[j] -= force;
      t[j] += tj;
    } else {
      later.push_back({j, -force, tj});
    }
  }
}
}  // namespace

namespace {
// The second half kick of velocity Verlet for one particle whose force is complete: v += dt/2
// (F/m + g), w += dt/2 T/I. Returns 1 when the result is not finite.
struct SecondHalfKick {
  Vec3* __restrict v;
  Vec3* __restrict w;
  const Vec3* __restrict f;
  const Vec3* __restrict t;
  const double* __restrict inv_m;
  const double* __restrict inv_i;
  Vec3 g;
  double half;
  bool rotate;
  int operator()(std::size_t p) const {
    v[p] += half * (f[p] * inv_m[p] + g);
    if (rotate) w[p] += (half * inv_i[p]) * t[p];
    return is_finite(v[p]) && is_finite(w[p]) ? 0 : 1;
  }
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
void Simulation::contacts(bool kick) {
  const std::size_t n = p_.size();
  const ContactConstants c = constants_;
  const Domain dom = settings_.domain;
  const bool periodic = dom.any_periodic();
  const double dt = dt_;
  const Vec3* x = p_.position.data();
  const Vec3* v = p_.velocity.data();
  const Vec3* w = p_.angular_velocity.data();
  const double* r = p_.radius.data();
  const double* m = p_.mass.data();
  const double* inv_i = p_.inv_inertia.data();
  Vec3* f = p_.force.data();
  Vec3* t = p_.torque.data();
  const std::uint32_t* first = pairs_.first.data();
  const std::uint32_t* partner = pairs_.partner.data();
  std::uint32_t* pair_contact = pair_contact_.data();
  const ContactHistory* history = contacts_.data();
  ContactHistory* next_history = contacts_next_.data();
  const auto no_history = static_cast<std::uint32_t>(pairs_.size());  // the empty last entry
  const int threads = omp_get_max_threads();
  deferred_.resize(std::size_t(threads));
  batches_.resize(std::size_t(threads));
  wall_batches_.resize(std::size_t(threads));
  const WallBatchLaw::Fn wall_law =
      walls_.empty() || !wall_laws_.uniform_choices ? nullptr : law_instance<WallBatchLaw>(wall_laws_.all.front());
  const PairBatchLaw::Fn batch_law = law_instance<PairBatchLaw>(c);
  const std::size_t n_walls = walls_.size();
  wall_loads_.assign(std::size_t(threads) * n_walls * 2, Vec3{});  // force, torque per thread and wall
  const std::uint32_t* near_walls = particles_near_walls_.data();
  const std::uint32_t* near_walls_end = near_walls + particles_near_walls_.size();
  double max_overlap = 0.0;
  // The second half kick (kick = true) is given to each particle in the sweep as soon as its force
  // is complete: its own pairs, its shares as a partner, its walls. A particle that is the partner
  // of an earlier thread's owner receives that share after the sweep: it and every particle below
  // the highest such partner (partner_reach_) are kicked then.
  const SecondHalfKick second_half_kick{p_.velocity.data(), p_.angular_velocity.data(), f, t, p_.inv_mass.data(),
                                        inv_i, gravity(), 0.5 * dt, !settings_.freeze_rotation};
  int any_bad = 0;
#pragma omp parallel reduction(max : max_overlap) reduction(| : any_bad)
  {
    const int team = omp_get_num_threads(), me = omp_get_thread_num();
    const std::size_t begin = n * std::size_t(me) / std::size_t(team);
    const std::size_t end = n * std::size_t(me + 1) / std::size_t(team);
    std::vector<PartnerShare>& later = deferred_[std::size_t(me)];
    ContactBatch& batch = batches_[std::size_t(me)];
    Vec3* my_wall_loads = wall_loads_.data() + std::size_t(me) * n_walls * 2;
    // The block's particles with walls within reach, in index order.
    const std::uint32_t* next_near_wall = std::lower_bound(near_walls, near_walls_end, std::uint32_t(begin));
    WallBatch& wall_batch = wall_batches_[std::size_t(me)];
    wall_batch.count = 0;
    auto walls_before = [&](std::size_t done) {  // the wall contacts of the particles before `done`
      for (; next_near_wall != near_walls_end && *next_near_wall < done; ++next_near_wall) {
        const std::uint32_t i = *next_near_wall;
        if (wall_batch.count + (wall_list_.first[i + 1] - wall_list_.first[i]) > WallBatch::kCapacity)
          wall_forces(wall_batch, wall_law, my_wall_loads, max_overlap);
        collect_wall_contacts(i, wall_batch);
      }
    };
    later.clear();
    for (std::size_t i = begin; i < end; ++i) {
      f[i] = Vec3{};
      t[i] = Vec3{};
    }

    // Batch by batch: the touching pairs, the law over them, their shares. The owner's shares are
    // summed and added once its last pair is done (a batch may end within an owner's pairs): the
    // same order of additions as a loop over the pairs owner by owner.
    const SweepPrefetch ahead_of{v, w, f, t, history, next_history};
    std::size_t next_kick = kick ? std::min(end, std::max<std::size_t>(begin, partner_reach_[begin])) : end;
    auto kick_before = [&](std::size_t limit) {  // the particles before `limit` are complete
      for (; next_kick < limit; ++next_kick) any_bad |= second_half_kick(next_kick);
    };
    PairCursor at{begin, 0};
    std::uint32_t next_contact = first[begin];  // this block's part of next_history
    OwnerSums sums{begin, Vec3{}, Vec3{}};
    while (at.owner < end) {
      const std::uint32_t count =
          periodic ? collect_touching<true>(at, end, x, r, first, partner, pair_contact, no_history, next_contact,
                                            dom, batch, ahead_of, n)
                   : collect_touching<false>(at, end, x, r, first, partner, pair_contact, no_history, next_contact,
                                             dom, batch, ahead_of, n);
      batch_law(batch, count, c, r, m, inv_i, v, w, history, dt);
      add_batch_shares(batch, count, end, f, t, next_history, sums, later, max_overlap);
      walls_before(sums.owner);  // the particles before the current owner have all their pair shares
      kick_before(wall_batch.count > 0 ? std::min<std::size_t>(sums.owner, wall_batch.particle[0]) : sums.owner);
    }
    if (begin < end) {
      f[sums.owner] += sums.force;
      t[sums.owner] += sums.torque;
    }
    walls_before(end);
    wall_forces(wall_batch, wall_law, my_wall_loads, max_overlap);
    kick_before(end);
  }
  for (const auto& shares : deferred_) {
    for (const PartnerShare& s : shares) {
      f[s.particle] += s.force;
      t[s.particle] += s.torque;
    }
  }
  if (kick) {  // the particles that received a share after the sweep, block by block
    for (int th = 0; th < threads; ++th) {
      const std::size_t begin = n * std::size_t(th) / std::size_t(threads);
      const std::size_t end = n * std::size_t(th + 1) / std::size_t(threads);
      const std::size_t reach = std::min(end, std::max<std::size_t>(begin, partner_reach_[begin]));
      for (std::size_t p = begin; p < reach; ++p) any_bad |= second_half_kick(p);
    }
  }
  bad_particle_ = -1;
  for (std::size_t i = 0; any_bad && i < n; ++i) {
    if (!is_finite(p_.velocity[i]) || !is_finite(p_.angular_velocity[i])) {
      bad_particle_ = std::int64_t(i);
      break;
    }
  }
  contacts_.swap(contacts_next_);
  max_overlap_seen_ = max_overlap;
  for (std::size_t k = 0; k < n_walls; ++k) {
    walls_[k].force = Vec3{};
    walls_[k].torque = Vec3{};
    for (int th = 0; th < threads; ++th) {
      walls_[k].force += wall_loads_[(std::size_t(th) * n_walls + k) * 2];
      walls_[k].torque += wall_loads_[(std::size_t(th) * n_walls + k) * 2 + 1];
    }
  }
}

// The wall contacts of particle i (which has walls within reach): the touching candidates go to
// the batch, the others lose their history and force.
void Simulation::collect_wall_contacts(std::uint32_t i, WallBatch& batch) {
  const Vec3 xi = p_.position[i];
  const double ri = p_.radius[i];
  const std::uint32_t* wall_of = wall_list_.wall.data();
  ContactHistory* whist = wall_list_.history.data();
  Vec3* wforce = wall_list_.force.data();
  const Wall* walls = walls_.data();

  const std::uint32_t k0 = wall_list_.first[i], count = wall_list_.first[i + 1] - k0;
  {  // The candidate arrays are read in order but sparsely (particles near walls only): prefetched.
    const std::size_t ahead = std::min<std::size_t>(k0 + 16, wall_list_.wall.size() - 1);
    __builtin_prefetch(&wall_of[ahead]);
    __builtin_prefetch(&whist[ahead], 1);
    __builtin_prefetch(&wforce[ahead], 1);
  }
  WallProximity near[kMaxWallCandidates];
  bool touching[kMaxWallCandidates];
  std::uint32_t touching_count = 0;
  for (std::uint32_t c = 0; c < count; ++c) {
    near[c] = wall_proximity(walls[wall_of[k0 + c]], xi);
    touching[c] = near[c].distance < ri;
    touching_count += touching[c] ? 1 : 0;
  }
  const bool several = touching_count > 1;
  for (std::uint32_t c = 0; c < count; ++c) {
    const std::uint32_t k = k0 + c;
    if (!touching[c] ||
        (several && edge_contact_hidden(c, near, touching, count,
                                        [&](std::size_t b) -> const Wall& { return walls[wall_of[k0 + b]]; },
                                        1e-6 * ri))) {
      if (whist[k].flags != 0) whist[k].reset();
      wforce[k] = Vec3{};
      continue;
    }
    const Wall& wall = walls[wall_of[k]];
    const std::uint32_t q = batch.count++;
    batch.particle[q] = i;
    batch.candidate[q] = k;
    batch.wall[q] = wall_of[k];
    const Vec3 lever = near[c].point - wall.origin;
    for (int a = 0; a < 3; ++a) {
      batch.normal[a][q] = near[c].normal[a];
      batch.point[a][q] = lever[a];
      batch.wall_velocity[a][q] = wall.current_velocity[a];
    }
    batch.distance[q] = near[c].distance;
  }
}

// The law over the batch of wall contacts (vectorised when the walls' laws make the same choices),
// then in contact order: the histories and forces stored, the thread's wall loads `load` (force,
// torque per wall) and each particle's force and torque added (its contacts summed first).
void Simulation::wall_forces(WallBatch& batch, WallBatchLaw::Fn law, Vec3* load, double& max_overlap) {
  if (batch.count == 0) return;
  const BodyArrays body{p_.radius.data(), p_.mass.data(), p_.inv_inertia.data(), p_.velocity.data(),
                        p_.angular_velocity.data()};
  ContactHistory* whist = wall_list_.history.data();
  if (law)
    law(batch, wall_laws_, body, whist, dt_);
  else
    wall_law_over_batch_any(batch, wall_laws_, body, whist, dt_);
  Vec3* wforce = wall_list_.force.data();
  Vec3 fi{}, ti{};
  for (std::uint32_t q = 0; q < batch.count; ++q) {
    const std::uint32_t i = batch.particle[q], k = batch.candidate[q], wall = batch.wall[q];
    max_overlap = std::max(max_overlap, (p_.radius[i] - batch.distance[q]) / p_.radius[i]);
    whist[k].tangential_spring = {batch.spring[0][q], batch.spring[1][q], batch.spring[2][q]};
    whist[k].rolling_spring = {batch.rolling_spring[0][q], batch.rolling_spring[1][q], batch.rolling_spring[2][q]};
    whist[k].flags = batch.flags[q];
    const Vec3 force{batch.force[0][q], batch.force[1][q], batch.force[2][q]};
    wforce[k] = force;
    load[2 * wall] -= force;
    load[2 * wall + 1] -= cross(Vec3{batch.point[0][q], batch.point[1][q], batch.point[2][q]}, force);
    fi += force;
    ti += Vec3{batch.torque[0][q], batch.torque[1][q], batch.torque[2][q]};
    if (q + 1 == batch.count || batch.particle[q + 1] != i) {
      p_.force[i] += fi;
      p_.torque[i] += ti;
      fi = Vec3{};
      ti = Vec3{};
    }
  }
  batch.count = 0;
}

std::string Simulation::describe_particle(std::uint32_t i) const {
  const Vec3& x = p_.position[i];
  const Vec3& v = p_.velocity[i];
  return fmt::format("particle id {} (radius {:.4g} m) at ({:.6g}, {:.6g}, {:.6g}) m moving at ({:.4g}, {:.4g}, {:.4g}) m/s",
                     p_.id[i], p_.radius[i], x.x, x.y, x.z, v.x, v.y, v.z);
}

void Simulation::check_stability() const {
  if (bad_particle_ < 0 && escaped_particle_ < 0 && !(max_overlap_seen_ > settings_.max_overlap_fraction)) return;
  // Only a failing run gets here: the message costs a scan of the masses and a string.
  const std::string when = fmt::format("step {} (t = {:.6g} s, dt = {:.4g} s, critical step {:.4g} s)", stats_.steps,
                                       time_, dt_, critical_time_step());
  if (bad_particle_ >= 0)
    throw SimulationError(fmt::format(
        "unstable run at {}: {} has a non-finite velocity (NaN or Inf). Likely cause: the time step is too large for "
        "the stiffness, or an input value is not a number.",
        when, describe_particle(static_cast<std::uint32_t>(bad_particle_))));
  if (escaped_particle_ >= 0) {
    const Domain& d = settings_.domain;
    throw SimulationError(fmt::format(
        "particle left the domain at {}: {} is outside [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] x [{:.6g}, {:.6g}] m. Likely "
        "cause: a missing or too soft wall (it passed through), or an unstable time step.",
        when, describe_particle(static_cast<std::uint32_t>(escaped_particle_)), d.lower.x, d.upper.x, d.lower.y,
        d.upper.y, d.lower.z, d.upper.z));
  }
  if (max_overlap_seen_ > settings_.max_overlap_fraction) {
    // Find the worst contact again (only on failure) to name it and the stiffness that governs it:
    // the particle law's for a pair, the wall's own law for a particle-wall contact.
    std::string where = "a particle-wall contact";
    std::string stiffness_of = "particle";
    double stiffness = law_.normal_stiffness;
    double worst = 0.0;
    const Domain& dom = settings_.domain;
    for (std::uint32_t i = 0; i + 1 < pairs_.first.size(); ++i) {
      for (std::uint32_t k = pairs_.first[i]; k < pairs_.first[i + 1]; ++k) {
        const std::uint32_t j = pairs_.partner[k];
        const double ov = p_.radius[i] + p_.radius[j] - norm(dom.minimum_image(p_.position[i] - p_.position[j]));
        const double frac = ov / std::min(p_.radius[i], p_.radius[j]);
        if (frac > worst) {
          worst = frac;
          where = fmt::format("the contact of particle ids {} and {}", p_.id[i], p_.id[j]);
        }
      }
    }
    for (std::uint32_t i = 0; i + 1 < wall_list_.first.size(); ++i) {
      for (std::uint32_t k = wall_list_.first[i]; k < wall_list_.first[i + 1]; ++k) {
        const Wall& w = walls_[wall_list_.wall[k]];
        const double frac = (p_.radius[i] - wall_proximity(w, p_.position[i]).distance) / p_.radius[i];
        if (frac > worst) {
          worst = frac;
          where = fmt::format("the contact of particle id {} with wall '{}'", p_.id[i], w.name);
          stiffness_of = fmt::format("wall '{}'", w.name);
          stiffness = w.law.normal_stiffness;
        }
      }
    }
    // Above the central-difference limit 2 sqrt(m/k) the integration itself is unstable: advising a
    // stiffer contact would make it worse.
    const double limit = 2.0 * critical_time_step();
    const std::string cause =
        dt_ > limit
            ? fmt::format("the time step ({:.4g} s) exceeds the stability limit 2 sqrt(m_min / k_max) = {:.4g} s: "
                          "lower settings.time_step (or time_step_fraction; 0.1-0.2 is usual)",
                          dt_, limit)
            : fmt::format("the normal stiffness of the {} contact law ({:.4g} N/m) is too low for the load (raise "
                          "it, or lower gravity), or the time step is too large",
                          stiffness_of, stiffness);
    throw SimulationError(fmt::format(
        "overlap blow-up at {}: {} overlaps by {:.1f}% of the smaller radius (limit {:.1f}%). Likely cause: {}.", when,
        where, 100.0 * max_overlap_seen_, 100.0 * settings_.max_overlap_fraction, cause));
  }
}

Simulation::ListState Simulation::list_state() const {
  return {pairs(), wall_list_, position_at_build_, wall_displacement_at_build_, rebuilds_since_reorder_};
}

void Simulation::restore(double time, const SimulationStats& stats, ListState lists) {
  time_ = time;
  stats_ = stats;
  pairs_ = std::move(lists.pairs);
  wall_list_ = std::move(lists.walls);
  position_at_build_ = std::move(lists.position_at_build);
  wall_displacement_at_build_ = std::move(lists.wall_displacement_at_build);
  rebuilds_since_reorder_ = lists.rebuilds_since_reorder;
  compact_pair_history();
  find_particles_near_walls();
  find_partner_reach();
  history_pending_ = false;
  lists_valid_ = true;
  setup_done_ = true;
}

double Simulation::translational_kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < p_.size(); ++i) e += 0.5 * p_.mass[i] * norm2(p_.velocity[i]);
  return e;
}

double Simulation::rotational_kinetic_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < p_.size(); ++i) e += 0.5 / p_.inv_inertia[i] * norm2(p_.angular_velocity[i]);
  return e;
}

double Simulation::potential_energy(double reference_height) const {
  const Vec3 g = gravity();
  const double g_len = norm(g);
  if (g_len == 0.0) return 0.0;
  const Vec3 up = -g / g_len;
  double e = 0.0;
  for (std::size_t i = 0; i < p_.size(); ++i) e += p_.mass[i] * g_len * (dot(p_.position[i], up) - reference_height);
  return e;
}

std::size_t Simulation::contact_count() const {
  std::size_t c = 0;
  for (std::uint32_t slot : pair_contact_) c += slot != kNoContact ? 1 : 0;
  return c;
}

}  // namespace trapdem
