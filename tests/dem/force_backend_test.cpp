// The force back end interface (force_backend.hpp) implemented a second time, as plainly as it can
// be: an O(N^2) loop over every pair of particles and every particle-wall pair calling the law's
// sub-models (contact/law.hpp), reading and writing the contact histories through the declared
// state (engine_state.hpp) exactly as the interface says, without the fused kick. The engine runs
// the same steps on it and on the threaded CPU back end at 1, 3 and 7 threads, through list
// rebuilds (particles re-ordered, histories archived and restored by ids) and a wall pushed into
// the packing; both must give the same trajectories. The all-pairs back end also checks at every
// pass that each touching pair and particle-wall contact is in the engine's lists (a contact the
// lists missed would be a force the fast back end never computes).
//
// Tolerance: 1e-12 m on positions, 1e-9 m/s on velocities, 1e-6 rad/s on spins after 300 steps.
// The two back ends add each particle's contact forces in different orders (the threaded one in
// pair order with partner shares and deferred shares, this one in (i, j) order), ~1e-16 relative
// per addition; in a dense packing that difference grows with the steps (the contacts' stiffness
// over the mass, ~(dt sqrt(k/m))^2 per step): measured <= 1e-16 m, 1.3e-13 m/s and 3e-9 rad/s after
// 300 steps and 20 rebuilds here.
// A lost contact, a share added twice or a history read from the wrong slot is a force of the order
// of a contact force, which moves a particle by ~1e-8 m in a step.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "dem/contact/law.hpp"
#include "dem/force_backend.hpp"
#include "dem/simulation.hpp"
#include "dem/thread_scope.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kDensity = 2500.0;
constexpr double kSpacing = 0.002;  // m; radii 0.95-1.07 mm: neighbours overlap
constexpr LawChoices kChoices{.rolling = RollingModel::elastic_plastic,
                              .lever_arm = RollingLeverArm::effective_radius,
                              .rolling_dashpot = true};

// Every pair and every particle-wall pair, for laws of the choices kChoices (the one instance this
// back end is compiled for; any other law is refused).
class AllPairsBackend final : public ForceBackend {
 public:
  std::string_view name() const override { return "all pairs (test)"; }
  bool fuses_second_half_kick() const override { return false; }
  void set_particle_law(const LawParams& params, const LawChoices& choices) override {
    require(choices);
    particle_ = params;
  }
  void add_wall_law(const LawParams& params, const LawChoices& choices) override {
    require(choices);
    walls_.push_back(params);
  }

  ForcePassResult compute_forces(EngineState& state, const ForcePass& pass) override {
    if (state.ghosts != 0 || pass.second_half_kick) throw std::logic_error("all-pairs back end: one process, no fused kick");
    ++passes_;
    Particles& p = state.particles;
    ContactLists& lists = state.lists;
    const std::size_t n = p.size();
    std::fill(p.force.begin(), p.force.end(), Vec3{});
    std::fill(p.torque.begin(), p.torque.end(), Vec3{});
    ForcePassResult result;

    // Particle pairs: the listed slot of (i, j), its last history, this pass's into contacts_next.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> slot_of;
    for (std::uint32_t i = 0; i + 1 < lists.pairs.first.size(); ++i)
      for (std::uint32_t k = lists.pairs.first[i]; k < lists.pairs.first[i + 1]; ++k)
        slot_of[{i, lists.pairs.partner[k]}] = k;
    ContactSlots next_slot(lists.pairs.size(), kNoContact);
    std::uint32_t next = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = i + 1; j < n; ++j) {
        const Vec3 d = pass.domain.minimum_image(p.position[i] - p.position[j]);
        const double distance = norm(d), reach = p.radius[i] + p.radius[j];
        if (!(distance < reach)) continue;
        const auto listed = slot_of.find({i, j});
        if (listed == slot_of.end())
          throw std::logic_error("touching pair of ids " + std::to_string(p.id[i]) + " and " + std::to_string(p.id[j]) +
                                 " not in the pair list");
        const std::uint32_t k = listed->second;
        ContactHistory h = lists.pair_contact[k] != kNoContact ? lists.contacts.get(lists.pair_contact[k]) : ContactHistory{};
        const double overlap = reach - distance;
        const Vec3 normal = d / distance;
        const ContactBodies b = reduce_bodies<kChoices, SecondBody::sphere>(
            Body{p.mass[i], p.radius[i], p.inv_inertia[i]}, Body{p.mass[j], p.radius[j], p.inv_inertia[j]}, overlap,
            distance);
        const ContactForce cf = ContactEvaluator<kChoices>::evaluate(particle_, b, normal, overlap,
                                                                     p.velocity[i] - p.velocity[j], p.angular_velocity[i],
                                                                     p.angular_velocity[j], h, pass.dt);
        const ContactTorques t = contact_torques(cf, b, normal);
        p.force[i] += cf.force;
        p.force[j] -= cf.force;
        p.torque[i] += t.on_i;
        p.torque[j] += t.on_j;
        lists.contacts_next.grow_to(next + 1);
        lists.contacts_next.set(next, h);
        next_slot[k] = next++;
        result.max_overlap_fraction = std::max(result.max_overlap_fraction, overlap / std::min(p.radius[i], p.radius[j]));
      }
    }
    lists.pair_contact = std::move(next_slot);
    lists.contacts.swap(lists.contacts_next);

    // Walls: the candidate's history in place; the others' reset, as the interface says.
    for (Wall& w : state.walls) w.force = w.torque = Vec3{};
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t c = lists.walls.first[i]; c < lists.walls.first[i + 1]; ++c) {
        const Wall& w = state.walls[lists.walls.wall[c]];
        if (!(wall_proximity(w, p.position[i]).distance < p.radius[i])) {
          lists.walls.history[c] = ContactHistory{};
          lists.walls.force[c] = Vec3{};
        }
      }
      for (std::uint32_t wall = 0; wall < state.walls.size(); ++wall) {
        Wall& w = state.walls[wall];
        const WallProximity near = wall_proximity(w, p.position[i]);
        if (!(near.distance < p.radius[i])) continue;
        std::uint32_t c = lists.walls.first[i];
        while (c < lists.walls.first[i + 1] && lists.walls.wall[c] != wall) ++c;
        if (c == lists.walls.first[i + 1])
          throw std::logic_error("particle id " + std::to_string(p.id[i]) + " touches wall '" + w.name +
                                 "' but is not its candidate");
        ContactHistory& h = lists.walls.history[c];
        const double overlap = p.radius[i] - near.distance;
        const ContactBodies b = reduce_bodies<kChoices, SecondBody::wall>(Body{p.mass[i], p.radius[i], p.inv_inertia[i]},
                                                                          Body{0.0, 0.0, 0.0}, overlap, near.distance);
        const ContactForce cf = ContactEvaluator<kChoices>::evaluate(walls_.at(wall), b, near.normal, overlap,
                                                                     p.velocity[i] - w.current_velocity,
                                                                     p.angular_velocity[i], Vec3{}, h, pass.dt);
        p.force[i] += cf.force;
        p.torque[i] += contact_torques(cf, b, near.normal).on_i;
        lists.walls.force[c] = cf.force;
        w.force -= cf.force;
        w.torque -= cross(near.point - w.origin, cf.force);
        result.max_overlap_fraction = std::max(result.max_overlap_fraction, overlap / p.radius[i]);
      }
    }
    return result;
  }

  int passes() const { return passes_; }

 private:
  static void require(const LawChoices& choices) {
    if (!(choices == kChoices)) throw std::invalid_argument("all-pairs back end: compiled for the EPSD law only");
  }
  LawParams particle_{};
  std::vector<LawParams> walls_;
  int passes_ = 0;
};

// A dense packing in a closed box of six walls, one side pushed into it: contacts stay, slide,
// form and break, and the lists are rebuilt (the particles re-ordered) many times in the run.
Simulation make_packing() {
  constexpr int kNx = 7, kNy = 6, kNz = 5;
  Particles p = jittered_lattice(77, kNx, kNy, kNz, kSpacing, kDensity);
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.03, 0.03, 0.03};
  s.max_overlap_fraction = 0.5;
  s.skin = 0.05e-3;  // m, small: the lists are rebuilt often
  ContactLaw floor_law = frictional_rolling_law();
  floor_law.normal_stiffness = 4.0e4;
  floor_law.static_friction = floor_law.kinetic_friction = 0.6;
  Simulation sim(std::move(p), frictional_rolling_law(), s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, floor_law));
  const std::size_t side = sim.add_wall(Wall::plane("side", {0, 0, 0}, {1, 0, 0}, frictional_rolling_law()));
  sim.set_wall_velocity(side, Vec3{0.02, 0.0, 0.0});
  // The other five sides 0.95 mm beyond the outer centres: every outer particle touches them.
  const ContactLaw law = frictional_rolling_law();
  sim.add_wall(Wall::plane("far side", {kNx * kSpacing, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("front", {0, 0, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("back", {0, kNy * kSpacing, 0}, {0, -1, 0}, law));
  sim.add_wall(Wall::plane("lid", {0, 0, 0.96e-3 + (kNz - 1) * kSpacing + 0.95e-3}, {0, 0, -1}, law));
  return sim;
}

}  // namespace

TEST(ForceBackend, AnAllPairsBackEndGivesTheThreadedBackEndsTrajectories) {
  constexpr int kSteps = 300;
  Simulation reference = make_packing();
  auto all_pairs = std::make_unique<AllPairsBackend>();
  const AllPairsBackend& plain = *all_pairs;
  reference.set_force_backend(std::move(all_pairs));
  EXPECT_EQ(reference.force_backend().name(), "all pairs (test)");
  std::vector<std::vector<Vec3>> reference_loads;  // per step, per wall: N
  for (int step = 0; step < kSteps; ++step) {
    reference.step();
    reference_loads.emplace_back();
    for (const Wall& w : reference.walls()) reference_loads.back().push_back(w.force);
  }
  EXPECT_EQ(plain.passes(), kSteps + 1);  // the initial forces, then one pass a step
  EXPECT_GE(reference.stats().rebuilds, 5);  // the lists rebuilt and the histories carried across
  EXPECT_GT(reference.contact_count(), 100u);

  for (const int threads : {1, 3, 7}) {
    const ThreadScope scope(threads);
    Simulation sim = make_packing();
    EXPECT_EQ(sim.force_backend().name(), "threaded CPU");
    EXPECT_TRUE(sim.force_backend().fuses_second_half_kick());
    double load_scale = 0.0, load_error = 0.0;  // N, the largest wall load and difference over the run
    for (int step = 0; step < kSteps; ++step) {
      sim.step();
      for (std::size_t k = 0; k < sim.walls().size(); ++k) {
        load_scale = std::max(load_scale, norm(reference_loads[step][k]));
        load_error = std::max(load_error, norm(sim.walls()[k].force - reference_loads[step][k]));
      }
    }
    EXPECT_EQ(sim.stats().rebuilds, reference.stats().rebuilds) << threads << " threads";
    EXPECT_EQ(sim.contact_count(), reference.contact_count()) << threads << " threads";
    const Particles& p = sim.particles();
    const Particles& q = reference.particles();
    std::map<std::int64_t, std::size_t> at;
    for (std::size_t i = 0; i < q.size(); ++i) at[q.id[i]] = i;
    double dx = 0.0, dv = 0.0, dw = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t j = at.at(p.id[i]);
      dx = std::max(dx, norm(p.position[i] - q.position[j]));
      dv = std::max(dv, norm(p.velocity[i] - q.velocity[j]));
      dw = std::max(dw, norm(p.angular_velocity[i] - q.angular_velocity[j]));
    }
    report("{} threads: max |dx| {:.1e} m, |dv| {:.1e} m/s, |dw| {:.1e} rad/s after {} steps, {} rebuilds; wall loads "
           "{:.1e} of {:.1e} N",
           threads, dx, dv, dw, kSteps, sim.stats().rebuilds, load_error, load_scale);
    EXPECT_LE(dx, 1e-12) << threads << " threads";
    EXPECT_LE(dv, 1e-9) << threads << " threads";
    EXPECT_LE(dw, 1e-6) << threads << " threads";
    EXPECT_GT(load_scale, 0.0);
    EXPECT_LE(load_error, 1e-9 * load_scale) << threads << " threads";
  }
}

TEST(ForceBackend, IsChosenBeforeTheFirstStepAndGetsEveryLaw) {
  Simulation sim = make_packing();
  sim.step();
  try {
    sim.set_force_backend(std::make_unique<AllPairsBackend>());
    FAIL() << "a back end set after the first step was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("before the first step"), std::string::npos) << e.what();
  }
  // The laws are handed over at once: a back end that cannot run a wall's law refuses it.
  Simulation other = make_packing();
  ContactLaw constant_torque = frictional_rolling_law();
  constant_torque.rolling_model = RollingModel::constant_torque;
  other.add_wall(Wall::plane("top", {0, 0, 0.02}, {0, 0, -1}, constant_torque));
  EXPECT_THROW(other.set_force_backend(std::make_unique<AllPairsBackend>()), std::invalid_argument);
}
