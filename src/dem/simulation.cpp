#include "dem/simulation.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>

#include <fmt/format.h>

#include "dem/cell_sort.hpp"
#include "core/errors.hpp"
#include "dem/decomposition.hpp"
#include "dem/integrator.hpp"
#include "dem/periodic_wrap.hpp"

namespace trapdem {

Simulation::Simulation(Particles particles, const ContactLaw& particle_law, SimulationSettings settings,
                       RigidBodies bodies)
    : backend_(make_threaded_cpu_backend()), law_(particle_law), settings_(settings) {
  state_.particles = std::move(particles);
  state_.bodies = std::move(bodies);
  law_.validate("particle contact law");
  backend_->set_particle_law(law_params(law_, law_), law_choices(law_));
  state_.lists.contacts = state_.lists.contacts_next = PairHistories(keeps_rolling_spring(law_choices(law_)));
  set_gravity(Vec3{0.0, 0.0, -9.81});
  for (int a = 0; a < 3; ++a) {
    if (!(settings_.domain.upper[a] > settings_.domain.lower[a]))
      throw InputError(fmt::format("domain: upper bound must exceed lower bound on axis {} (got {} .. {})", "xyz"[a],
                                   settings_.domain.lower[a], settings_.domain.upper[a]));
  }
  if (!state_.bodies.empty()) {
    check_bodies_allowed("rigid bodies");
    state_.bodies.locate_members(state_.particles.id);  // every particle a member
  }
  if (settings_.skin > 0.0) {
    skin_ = settings_.skin;
  } else if (!state_.particles.empty()) {
    const std::vector<double>& r = state_.particles.radius;
    skin_ = 0.2 * 2.0 * std::accumulate(r.begin(), r.end(), 0.0) / double(r.size());
  } else {
    throw InputError("simulation: the Verlet skin cannot be derived without particles; set settings.skin (m)");
  }
  if (settings_.time_step > 0.0) {
    dt_ = settings_.time_step;
  } else if (!state_.particles.empty()) {
    dt_ = settings_.time_step_fraction * critical_time_step();
  } else {
    throw InputError("simulation: the time step cannot be derived without particles; set settings.time_step (s)");
  }
}

Simulation::Simulation(Simulation&&) noexcept = default;
Simulation& Simulation::operator=(Simulation&&) noexcept = default;
Simulation::~Simulation() = default;

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

void Simulation::set_rotating_frame(RotatingFrame frame) {
  const double length = norm(frame.axis);
  if (!(length > 0.0) || !std::isfinite(length))
    throw InputError("rotating frame: the axis direction must be a non-zero finite vector");
  if (!frame.spin) throw InputError("rotating frame: no angular velocity given (spin)");
  frame.axis = frame.axis / length;
  frame_ = std::make_unique<RotatingFrame>(std::move(frame));
}

void Simulation::clear_rotating_frame() { frame_.reset(); }

std::size_t Simulation::add_wall(Wall wall) {
  const std::string where = "wall '" + wall.name + "'";
  wall.law.validate(where);
  if (combines_materials(wall.law))  // the contact's other body: the particles' material
    law_.validate_material(fmt::format("particle contact law (the particles' material, for the {} law of {})",
                                       to_string(wall.law.normal_model), where));
  backend_->add_wall_law(law_params(wall.law, law_), law_choices(wall.law));
  state_.walls.push_back(std::move(wall));
  invalidate_lists();
  return state_.walls.size() - 1;
}

void Simulation::set_force_backend(std::unique_ptr<ForceBackend> backend) {
  if (setup_done_) throw InputError("a force back end is set before the first step");
  if (!backend) throw InputError("set_force_backend: no back end given");
  backend->set_particle_law(law_params(law_, law_), law_choices(law_));
  for (const Wall& w : state_.walls) backend->add_wall_law(law_params(w.law, law_), law_choices(w.law));
  backend_ = std::move(backend);
}

void Simulation::set_wall_velocity(std::size_t k, std::function<Vec3(double)> velocity) {
  state_.walls.at(k).velocity = std::move(velocity);
}

void Simulation::set_wall_velocity(std::size_t k, const Vec3& velocity) {
  set_wall_velocity(k, [velocity](double) { return velocity; });
}

void Simulation::restore_wall_state(std::size_t k, const Vec3& origin, const Vec3& displacement, const Vec3& force,
                                    const Vec3& torque, const Vec3& current_velocity) {
  Wall& w = state_.walls.at(k);
  w.origin = origin;
  w.displacement = displacement;
  w.force = force;
  w.torque = torque;
  w.current_velocity = current_velocity;
}

std::size_t Simulation::find_wall(const std::string& name) const {
  for (std::size_t k = 0; k < state_.walls.size(); ++k)
    if (state_.walls[k].name == name) return k;
  throw InputError(fmt::format("no wall named '{}'", name));
}

void Simulation::add_particle(std::int64_t id, const Vec3& x, double radius, double density, const Vec3& v) {
  if (!state_.bodies.empty())
    throw InputError(fmt::format("particle {}: a run with rigid bodies takes bodies only (a lone sphere: a body of "
                                 "one member, add_body)", id));
  if (!(radius > 0.0) || !(density > 0.0))
    throw InputError(fmt::format("particle {}: radius ({} m) and density ({} kg/m3) must be positive", id, radius, density));
  drop_ghosts();  // the owned particles come first
  // Appending keeps the existing indices: the lists' history stays valid.
  state_.particles.add(id, x, radius, density, v);
  invalidate_lists();
}

void Simulation::remove_particles(const std::vector<std::uint32_t>& indices) {
  Particles& p = state_.particles;
  if (indices.empty()) return;
  if (!state_.bodies.empty()) throw InputError("remove_particles: the particles are members of rigid bodies");
  if (!history_pending_ && !state_.lists.pairs.first.empty()) {
    pending_history_.store_pairs(state_.lists.pairs, state_.lists.pair_contact, state_.lists.contacts, p.id);
    pending_history_.store_walls(state_.lists.walls, p.id);
    history_pending_ = true;
  }
  std::vector<char> drop(owned_count(), 0);
  for (auto i : indices) drop.at(i) = 1;
  drop_ghosts();
  std::vector<std::uint32_t> keep;
  for (std::uint32_t i = 0; i < p.size(); ++i)
    if (!drop[i]) keep.push_back(i);
  p.permute(keep);
  invalidate_lists();
}

void Simulation::add_body(std::int64_t body_id, std::int64_t first_member_id, const ClumpTemplate& shape,
                          double density, const Vec3& position, const Quaternion& orientation, const Vec3& velocity,
                          const Vec3& angular_velocity) {
  check_bodies_allowed("add_body");
  if (state_.bodies.empty() && !state_.particles.empty())
    throw InputError(fmt::format("body {}: this run's particles are free spheres; a run takes either spheres or "
                                 "rigid bodies (a lone sphere: a body of one member)", body_id));
  // Appending keeps the existing indices: the lists' history stays valid until the rebuild.
  add_rigid_body(state_.bodies, state_.particles, body_id, first_member_id, shape, density, position, orientation,
                 velocity, angular_velocity);
  invalidate_lists();
}

void Simulation::check_bodies_allowed(const char* what) const {
  if (decomposition_)
    throw InputError(fmt::format("{}: rigid bodies run on one process (a body's members would cross ranks); run "
                                 "without ranks", what));
  for (int a = 0; a < 3; ++a)
    if (settings_.domain.periodic[a])
      throw InputError(fmt::format("{}: rigid bodies need bounded axes (the {} axis is periodic)", what, "xyz"[a]));
}

void Simulation::restore_bodies(RigidBodies bodies) {
  if (!bodies.empty()) check_bodies_allowed("restore_bodies");
  state_.bodies = std::move(bodies);
  invalidate_lists();
}

double Simulation::critical_time_step() const {
  const Particles& p = state_.particles;
  if (p.empty()) return std::numeric_limits<double>::infinity();
  std::vector<const ContactLaw*> wall_laws;
  for (const Wall& w : state_.walls) wall_laws.push_back(&w.law);
  double t = std::numeric_limits<double>::infinity();
  const RigidBodies& bodies = state_.bodies;
  if (!bodies.empty()) {
    // A contact force on a member turns its body too (contact_time_scale_mass), at most at the
    // farthest reach of a member's surface.
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const BodyContactScale scale = body_contact_scale(bodies, p, b);
      t = std::min(t, trapdem::critical_time_step(law_, wall_laws, scale.mass, scale.smallest_radius));
    }
    return t;
  }
  for (std::size_t i = 0; i < p.size(); ++i)
    t = std::min(t, trapdem::critical_time_step(law_, wall_laws, p.mass[i], p.radius[i]));
  return t;
}

void Simulation::run(std::int64_t steps) {
  for (std::int64_t s = 0; s < steps; ++s) step();
}

// One time step, for one process and for a rank of a decomposition alike: velocity Verlet as
// LAMMPS's nve/sphere does it (half kick, drift, forces at the new positions with the half-step
// velocities, half kick). Second order in dt for conservative forces; the dashpot sees velocities
// half a step old, which is first order and standard in DEM. The exchanges of a decomposition
// (halo.cpp) sit between the parts and do nothing on one process.
void Simulation::step() {
  // The fused kick: the second half kick inside the force pass, as soon as a particle's force is
  // complete, where the back end can (ForceBackend::fuses_second_half_kick). Not on ranks (a force
  // is complete only once the ghosts' shares are back) nor in a rotating frame (its kick needs the
  // positions after the sweep).
  // Nor with rigid bodies: a member's force is complete before its body's.
  const bool with_bodies = !state_.bodies.empty();
  const bool fused_kick = backend_->fuses_second_half_kick() && !decomposition_ && !frame_ && !with_bodies;
  if (!setup_done_) {  // forces of the initial state, so the first half kick sees them
    if (with_bodies) place_members(state_.bodies, state_.particles, true);
    rebuild_lists_agreed();
    forces(false);
    if (with_bodies) reduce_member_loads(state_.bodies, state_.particles);
    setup_done_ = true;
  }
  integrate_positions();  // first half kick and drift
  switch (agree_on_next_lists()) {
    case NextLists::stop: check_stability_agreed(); break;  // throws: stop before the particle would migrate
    case NextLists::rebuild: rebuild_lists_agreed(); break;
    case NextLists::keep: update_ghosts(); break;
  }
  forces(fused_kick);
  if (with_bodies) {  // the members' loads reduced onto the bodies in the kick's pass
    const std::optional<FrameKick> frame = frame_kick_now();
    bad_particle_ = bodies_second_half_kick(state_.bodies, state_.particles, body_kick(frame ? &*frame : nullptr))
                        ? first_non_finite_particle()
                        : -1;
  } else if (!fused_kick) {
    bad_particle_ = kick_owned() ? first_non_finite_particle() : -1;  // second half kick
  }
  stats_.ghost_steps += std::int64_t(state_.ghosts);
  ++stats_.steps;
  check_stability_agreed();
}

SecondHalfKick Simulation::second_half_kick() {
  Particles& p = state_.particles;
  return {p.velocity.data(),    p.angular_velocity.data(), p.force.data(), p.torque.data(),
          p.inv_mass.data(),    p.inv_inertia.data(),      gravity(),      0.5 * dt_,
          !settings_.freeze_rotation, spin_retention(law_, dt_)};
}

std::int64_t Simulation::first_non_finite_particle() const {
  const Particles& p = state_.particles;
  for (std::size_t i = 0; i < owned_count(); ++i)
    if (!is_finite(p.velocity[i]) || !is_finite(p.angular_velocity[i])) return std::int64_t(i);
  return -1;
}

void Simulation::find_particles_near_walls() {
  state_.lists.particles_near_walls.clear();
  for (std::uint32_t i = 0; i + 1 < state_.lists.walls.first.size(); ++i)
    if (state_.lists.walls.first[i + 1] > state_.lists.walls.first[i]) state_.lists.particles_near_walls.push_back(i);
}

// ContactLists::partner_reach[i]: one past the highest partner of the owners below i (0 when none),
// for a back end's fused second half kick.
void Simulation::find_partner_reach() {
  const PairList& pairs = state_.lists.pairs;
  std::vector<std::uint32_t>& reach = state_.lists.partner_reach;
  const std::size_t n = pairs.first.empty() ? 0 : pairs.first.size() - 1;
  reach.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t highest = pairs.first[i + 1] > pairs.first[i] ? pairs.partner[pairs.first[i + 1] - 1] + 1 : 0;
    reach[i + 1] = std::max(reach[i], highest);
  }
}

// Room for a history per listed pair in both arrays (a thread's block writes from index
// first[begin] on, and every listed pair may touch). Grown only: the pages of a larger earlier
// list stay, and nothing is written but the empty entry at index pairs.size(), where a contact that
// has just formed reads its history from.
void Simulation::size_contact_arrays() {
  const std::size_t needed = state_.lists.pairs.size() + 1;
  state_.lists.contacts.grow_to(needed);
  state_.lists.contacts_next.grow_to(needed);
  state_.lists.contacts.set(state_.lists.pairs.size(), ContactHistory{});
  state_.lists.contacts_next.set(state_.lists.pairs.size(), ContactHistory{});
}

// The per-listed-pair history of a checkpoint into the compact form.
void Simulation::compact_pair_history() {
  size_contact_arrays();
  state_.lists.pair_contact.assign(state_.lists.pairs.size(), kNoContact);
  std::uint32_t found = 0;
  for (std::size_t k = 0; k < state_.lists.pairs.history.size(); ++k) {
    if (!state_.lists.pairs.history[k].touching()) continue;
    state_.lists.contacts.set(found, state_.lists.pairs.history[k]);
    state_.lists.pair_contact[k] = found++;
  }
  state_.lists.pairs.history.clear();
  state_.lists.pairs.history.shrink_to_fit();
}

std::vector<ContactHistory> Simulation::pair_history() const {
  const ContactLists& lists = state_.lists;
  std::vector<ContactHistory> history(lists.pairs.size());
  for (std::size_t k = 0; k < lists.pair_contact.size(); ++k)
    if (lists.pair_contact[k] != kNoContact) history[k] = lists.contacts.get(lists.pair_contact[k]);
  return history;
}

PairList Simulation::pairs() const {
  PairList copy{state_.lists.pairs.first, state_.lists.pairs.partner, pair_history()};
  return copy;
}

std::optional<FrameKick> Simulation::frame_kick_now() const {
  if (!frame_) return std::nullopt;
  return FrameKick(*frame_, time_, 0.5 * dt_);
}

BodyKick Simulation::body_kick(const FrameKick* frame) const {
  return {gravity(), 0.5 * dt_, !settings_.freeze_rotation, spin_retention(law_, dt_), frame};
}

void Simulation::integrate_positions() {
  Particles& p = state_.particles;
  // Particles added since the last build have no reference position: the lists are invalid then
  // and will be rebuilt anyway.
  const bool track = lists_valid_ && state_.lists.position_at_build.size() == p.size();
  if (!state_.bodies.empty()) {
    const std::optional<FrameKick> frame = frame_kick_now();
    const DriftReport drift = bodies_first_half_kick_and_drift(
        state_.bodies, p, body_kick(frame ? &*frame : nullptr),
        track ? state_.lists.position_at_build.data() : nullptr, settings_.domain);
    displacements_ = drift.displacements;
    escaped_particle_ = drift.escaped;
    move_walls(state_.walls, time_, dt_);
    time_ += dt_;
    return;
  }
  if (frame_) frame_first_half_kick(p, owned_count(), FrameKick(*frame_, time_, 0.5 * dt_), 0.5 * dt_);
  const Vec3* at_build = track ? state_.lists.position_at_build.data() : nullptr;
  const DriftReport drift = first_half_kick_and_drift(p, owned_count(), at_build, gravity(), dt_,
                                                      settings_.domain, !settings_.freeze_rotation);
  displacements_ = drift.displacements;
  escaped_particle_ = drift.escaped;
  move_walls(state_.walls, time_, dt_);
  time_ += dt_;
}

// A pair not listed was at least the skin apart at the build (build_pairs), a particle not a wall's
// candidate at least the skin from it (build_wall_candidates). A pair's gap shrinks by at most
// |d_i - d_j| (bounded by DisplacementsSinceBuild::pair_bound), a particle's gap to a wall by at
// most |d_i - D| for the wall's translation D (DisplacementsSinceBuild::wall_bound). Rebuilt when
// either bound could reach the skin: the lists then still hold every contact. And rebuilt when a
// particle has moved more than the skin, even with the others: the build's bookkeeping (its
// periodic image, and on a decomposition its rank) then never lags a particle by more than that.
// The bounds compare with the skin the lists were built with, so a set_skin between builds leaves
// them exact.
bool Simulation::lists_outdated(const DisplacementsSinceBuild& all) const {
  const double skin = state_.lists.skin_at_build;
  if (!lists_valid_ || all.pair_bound() > skin || all.max_length2 > skin * skin) return true;
  for (std::size_t k = 0; k < state_.walls.size(); ++k)
    if (all.wall_bound(state_.walls[k].displacement - state_.lists.wall_displacement_at_build[k]) > skin)
      return true;
  return false;
}

void Simulation::set_skin(double skin) {
  if (!(skin > 0.0) || !std::isfinite(skin))
    throw InputError(fmt::format("simulation: the Verlet skin must be a positive length in m (got {})", skin));
  skin_ = skin;
}

void Simulation::rebuild_lists() {
  Particles& p = state_.particles;
  const double started = omp_get_wtime();
  ++stats_.rebuilds;
  const Domain& dom = settings_.domain;
  HistoryArchive& archive = archive_;
  if (history_pending_) {
    archive = std::move(pending_history_);
    pending_history_ = HistoryArchive{};
    history_pending_ = false;
  } else {
    archive.store_pairs(state_.lists.pairs, state_.lists.pair_contact, state_.lists.contacts, p.id);
    archive.store_walls(state_.lists.walls, p.id);
  }
  wrap_periodic(p, dom);

  double r_max = p.empty() ? 0.0 : *std::max_element(p.radius.begin(), p.radius.end());
  if (decomposition_) r_max = decomposition_->max(r_max);
  const double cell = 2.0 * r_max + skin_;  // m, also the ghosts' range on a decomposition
  for (int a = 0; a < 3; ++a) {
    if (dom.periodic[a] && dom.length(a) < 2.0 * cell)
      throw InputError(fmt::format(
          "periodic axis {}: the domain length {} m must be at least twice the interaction range {} m", "xyz"[a],
          dom.length(a), cell));
  }
  if (decomposition_) {  // the ghosts go (drop_ghosts archived nothing more: the archive holds it all)
    p.truncate(owned_count());
    state_.ghosts = 0;
    decomposition_->migrate(p, archive, cell);
  }
  CellSort cells = sort_into_cells(p.position, dom, cell);
  const bool reorder = settings_.reorder_every > 0 && rebuilds_since_reorder_ % settings_.reorder_every == 0;
  ++rebuilds_since_reorder_;
  if (reorder) {
    p.permute(cells.order);
    if (!state_.bodies.empty()) state_.bodies.follow_particle_permutation(cells.order);
    cells = in_cell_order(std::move(cells));
  }
  if (decomposition_) {
    state_.ghosts = decomposition_->exchange_ghosts(p, cell);
    if (state_.ghosts > 0) cells = sort_into_cells(p.position, dom, cell);
  }
  build_pairs(p, cells, dom, skin_, state_.lists.pairs);
  if (!state_.bodies.empty()) exclude_pairs_within_bodies(state_.lists.pairs, state_.bodies.body_of_particle);
  if (state_.ghosts > 0) keep_pairs_computed_here(state_.lists.pairs, owned_count(), p.id);
  size_contact_arrays();
  build_wall_candidates(p, owned_count(), state_.walls, skin_, state_.lists.walls);
  archive.restore(state_.lists.pairs, state_.lists.walls, p.id, state_.lists.pair_contact, state_.lists.contacts);

  find_particles_near_walls();
  find_partner_reach();
  state_.lists.position_at_build = p.position;
  state_.lists.wall_displacement_at_build.resize(state_.walls.size());
  for (std::size_t k = 0; k < state_.walls.size(); ++k)
    state_.lists.wall_displacement_at_build[k] = state_.walls[k].displacement;
  state_.lists.skin_at_build = skin_;
  lists_valid_ = true;
  stats_.rebuild_seconds += omp_get_wtime() - started;
}

Simulation::ListState Simulation::list_state() const {
  const ContactLists& lists = state_.lists;
  return {pairs(),           lists.walls, lists.position_at_build, lists.wall_displacement_at_build,
          rebuilds_since_reorder_, lists.skin_at_build};
}

void Simulation::drop_ghosts() {
  Particles& p = state_.particles;
  if (state_.ghosts == 0) return;
  if (!history_pending_ && !state_.lists.pairs.first.empty()) {
    pending_history_.store_pairs(state_.lists.pairs, state_.lists.pair_contact, state_.lists.contacts, p.id);
    pending_history_.store_walls(state_.lists.walls, p.id);
    history_pending_ = true;
  }
  p.truncate(owned_count());
  state_.ghosts = 0;
  invalidate_lists();
}

void Simulation::restore(double time, const SimulationStats& stats, ListState lists, std::size_t ghosts) {
  if (ghosts > state_.particles.size() || (ghosts > 0 && !decomposition_))
    throw InputError(fmt::format("restore: {} ghosts among {} particles{}", ghosts, state_.particles.size(),
                                 decomposition_ ? "" : " without a decomposition"));
  state_.ghosts = ghosts;
  time_ = time;
  stats_ = stats;
  state_.lists.pairs = std::move(lists.pairs);
  state_.lists.walls = std::move(lists.walls);
  state_.lists.position_at_build = std::move(lists.position_at_build);
  state_.lists.wall_displacement_at_build = std::move(lists.wall_displacement_at_build);
  rebuilds_since_reorder_ = lists.rebuilds_since_reorder;
  state_.lists.skin_at_build = lists.skin_at_build > 0.0 ? lists.skin_at_build : skin_;
  if (!state_.bodies.empty()) {  // the particles are in the checkpoint's order; their forces, the checkpoint's
    state_.bodies.locate_members(state_.particles.id);
    place_members(state_.bodies, state_.particles, true);  // the same bits: placed by the same formula
    reduce_member_loads(state_.bodies, state_.particles);
  }
  compact_pair_history();
  find_particles_near_walls();
  find_partner_reach();
  history_pending_ = false;
  lists_valid_ = true;
  setup_done_ = true;
}

void Simulation::resume_from_histories(double time, const SimulationStats& stats, HistoryArchive histories) {
  time_ = time;
  stats_ = stats;
  state_.ghosts = 0;
  state_.lists.pairs = PairList{};
  state_.lists.walls = WallList{};
  state_.lists.pair_contact.clear();
  if (decomposition_) {
    // Each rank keeps its particles, a pair's history with the lower id (the rank that computes the
    // pair, keep_pairs_computed_here) and a wall contact's with its particle.
    decomposition_->adopt(state_.particles, settings_.domain);
    std::vector<std::int64_t> mine = state_.particles.id;
    std::sort(mine.begin(), mine.end());
    auto here = [&](std::int64_t id) { return std::binary_search(mine.begin(), mine.end(), id); };
    std::erase_if(histories.pairs, [&](const HistoryArchive::PairRecord& r) { return !here(r.low); });
    std::erase_if(histories.walls, [&](const HistoryArchive::WallRecord& r) { return !here(r.particle); });
  }
  if (!state_.bodies.empty()) {
    state_.bodies.locate_members(state_.particles.id);
    place_members(state_.bodies, state_.particles, true);
    reduce_member_loads(state_.bodies, state_.particles);
  }
  pending_history_ = std::move(histories);
  history_pending_ = true;
  invalidate_lists();
  setup_done_ = true;  // the particles' forces are the checkpoint's: the next step starts with a kick
}

}  // namespace trapdem
