// The engine's forces against a plain O(N^2) evaluation of the same contact law: a dense,
// polydisperse packing with rolling resistance, against a floor, a moving side wall and a finite
// rectangle (walls of three different rolling models), after one step at 1, 3 and 7 threads.
//
// The reference loops over every pair of particles and every particle-wall pair and calls the law's
// sub-models directly (contact/law.hpp: reduce_bodies, ContactEvaluator, contact_torques): no
// neighbour list, no batches, no thread blocks, no deferred shares. It reads the state the engine's
// force pass read: the positions after the step (the second half kick moves no particle), the
// half-step velocities v - dt/2 (F/m + g) and w - dt/2 T/I recovered from the end of the step, and
// the contact histories of the step before (Simulation::pairs, wall_candidates, keyed by ids).
//
// Tolerance, per particle: 1e-10 x the sum of the magnitudes of its contact forces (torques: that
// sum x its radius). The engine adds a particle's contacts in another order than the reference
// (pair order, partner shares, walls), ~1e-16 relative per addition, and the recovered half-step
// velocities differ from the engine's by ~1e-16 of the end-of-step velocity, which the dashpot
// multiplies by c_n dt / m* ~ 1 at most: round-off of ~1e-15 of the force scale in all. A wrong
// sign, a lost share or a contact read twice is of the order of a contact force.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "dem/contact/law.hpp"
#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kDensity = 2500.0;
constexpr double kSpacing = 0.002;  // m, lattice spacing; radii 0.95-1.07 mm: neighbours overlap
constexpr int kNx = 8, kNy = 8, kNz = 6;

// The laws, each with the choices its instance below is compiled for.
ContactLaw particle_law() { return frictional_rolling_law(); }  // EPSD rolling, friction 0.4 / 0.3
constexpr LawChoices kParticleChoices{.rolling = RollingModel::elastic_plastic,
                                      .lever_arm = RollingLeverArm::effective_radius,
                                      .rolling_dashpot = true};

ContactLaw floor_law() {  // EPSD as the particles, stiffer, more friction
  ContactLaw law = particle_law();
  law.normal_stiffness = 4.0e4;
  law.static_friction = law.kinetic_friction = 0.6;
  return law;
}
ContactLaw side_law() {  // constant rolling torque
  ContactLaw law = particle_law();
  law.rolling_model = RollingModel::constant_torque;
  law.lever_arm = RollingLeverArm::average_radius;
  return law;
}
ContactLaw plate_law() {  // no rolling resistance
  ContactLaw law = particle_law();
  law.rolling_friction = 0.0;
  law.restitution = 0.8;
  return law;
}
constexpr LawChoices kSideChoices{.rolling = RollingModel::constant_torque};
constexpr LawChoices kPlateChoices{};

Simulation make_packing() {
  Particles p = jittered_lattice(2024, kNx, kNy, kNz, kSpacing, kDensity);
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.03, 0.03, 0.03};
  s.max_overlap_fraction = 0.5;
  Simulation sim(std::move(p), particle_law(), s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, floor_law()));
  const std::size_t side = sim.add_wall(Wall::plane("side", {0, 0, 0}, {1, 0, 0}, side_law()));
  sim.set_wall_velocity(side, Vec3{0.02, 0.0, 0.0});  // pushes into the packing
  // A rectangular plate pressed against the packing's far side (y = max), away from the other
  // walls: every particle of the last row within its extent touches it.
  sim.add_wall(Wall::rectangle("plate", {0.5 * kNx * kSpacing, (kNy - 0.5) * kSpacing + 0.85e-3, 0.006}, {1, 0, 0},
                               0.005, {0, 0, 1}, 0.003, plate_law()));
  sim.set_gravity(Vec3{0, 0, -9.81});
  return sim;
}

struct Loads {
  std::vector<Vec3> force, torque;  // per particle id - 1
  std::vector<double> scale;        // N, sum of |contact force| per particle
};

using PairKey = std::pair<std::int64_t, std::int64_t>;  // ids, the history expressed for the first as body i

// The histories the engine will read in the next step, keyed by particle ids.
struct Histories {
  std::map<PairKey, ContactHistory> pairs;
  std::map<std::pair<std::int64_t, std::uint32_t>, ContactHistory> walls;
};
Histories capture(const Simulation& sim) {
  Histories h;
  const Particles& p = sim.particles();
  const PairList pairs = sim.pairs();
  for (std::uint32_t i = 0; i + 1 < pairs.first.size(); ++i)
    for (std::uint32_t k = pairs.first[i]; k < pairs.first[i + 1]; ++k)
      if (pairs.history[k].touching()) h.pairs[{p.id[i], p.id[pairs.partner[k]]}] = pairs.history[k];
  const WallList& walls = sim.wall_candidates();
  for (std::uint32_t i = 0; i + 1 < walls.first.size(); ++i)
    for (std::uint32_t k = walls.first[i]; k < walls.first[i + 1]; ++k)
      if (walls.history[k].touching()) h.walls[{p.id[i], walls.wall[k]}] = walls.history[k];
  return h;
}

ContactHistory pair_history(const Histories& h, std::int64_t a, std::int64_t b) {
  if (auto it = h.pairs.find({a, b}); it != h.pairs.end()) return it->second;
  if (auto it = h.pairs.find({b, a}); it != h.pairs.end()) {
    ContactHistory flipped = it->second;
    flipped.tangential_spring = -flipped.tangential_spring;
    flipped.rolling_spring = -flipped.rolling_spring;
    return flipped;
  }
  return {};
}

template <LawChoices kLaw>
void wall_contact(const LawParams& law, const Body& body, double distance, const Vec3& n, const Vec3& v_rel,
                  const Vec3& w, ContactHistory h, double dt, Vec3& f, Vec3& t, double& scale) {
  const double overlap = body.radius - distance;
  const ContactBodies b = reduce_bodies<kLaw, SecondBody::wall>(body, Body{0.0, 0.0, 0.0}, overlap, distance);
  const ContactForce cf = ContactEvaluator<kLaw>::evaluate(law, b, n, overlap, v_rel, w, Vec3{}, h, dt);
  f += cf.force;
  t += contact_torques(cf, b, n).on_i;
  scale += norm(cf.force);
}

// The O(N^2) reference over the state the engine's last force pass read (see the file's header).
Loads reference_loads(const Simulation& sim, const Histories& histories) {
  const Particles& p = sim.particles();
  const std::size_t n = p.size();
  const double dt = sim.time_step(), half = 0.5 * dt;
  const Vec3 g = sim.gravity();
  std::vector<Vec3> v(n), w(n);
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = p.velocity[i] - half * (p.force[i] * p.inv_mass[i] + g);
    w[i] = p.angular_velocity[i] - (half * p.inv_inertia[i]) * p.torque[i];
  }
  Loads out{std::vector<Vec3>(n), std::vector<Vec3>(n), std::vector<double>(n, 0.0)};
  auto slot = [&](std::size_t i) { return std::size_t(p.id[i] - 1); };
  const LawParams particle = law_params(particle_law(), particle_law());
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec3 d = p.position[i] - p.position[j];
      const double dist = norm(d), reach = p.radius[i] + p.radius[j];
      if (!(dist < reach)) continue;
      const Vec3 normal = d / dist;
      const double overlap = reach - dist;
      const ContactBodies b = reduce_bodies<kParticleChoices, SecondBody::sphere>(
          Body{p.mass[i], p.radius[i], p.inv_inertia[i]}, Body{p.mass[j], p.radius[j], p.inv_inertia[j]}, overlap,
          dist);
      ContactHistory h = pair_history(histories, p.id[i], p.id[j]);
      const ContactForce cf =
          ContactEvaluator<kParticleChoices>::evaluate(particle, b, normal, overlap, v[i] - v[j], w[i], w[j], h, dt);
      const ContactTorques t = contact_torques(cf, b, normal);
      out.force[slot(i)] += cf.force;
      out.force[slot(j)] -= cf.force;
      out.torque[slot(i)] += t.on_i;
      out.torque[slot(j)] += t.on_j;
      out.scale[slot(i)] += norm(cf.force);
      out.scale[slot(j)] += norm(cf.force);
    }
  }
  const std::vector<Wall>& walls = sim.walls();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::uint32_t k = 0; k < walls.size(); ++k) {
      const WallProximity near = wall_proximity(walls[k], p.position[i]);
      if (!(near.distance < p.radius[i])) continue;
      const ContactHistory h = [&] {
        auto it = histories.walls.find({p.id[i], k});
        return it == histories.walls.end() ? ContactHistory{} : it->second;
      }();
      const LawParams law = law_params(walls[k].law, particle_law());
      const Body body{p.mass[i], p.radius[i], p.inv_inertia[i]};
      const Vec3 v_rel = v[i] - walls[k].current_velocity;
      Vec3& f = out.force[slot(i)];
      Vec3& t = out.torque[slot(i)];
      double& s = out.scale[slot(i)];
      if (walls[k].name == "floor") wall_contact<kParticleChoices>(law, body, near.distance, near.normal, v_rel, w[i], h, dt, f, t, s);
      if (walls[k].name == "side") wall_contact<kSideChoices>(law, body, near.distance, near.normal, v_rel, w[i], h, dt, f, t, s);
      if (walls[k].name == "plate") wall_contact<kPlateChoices>(law, body, near.distance, near.normal, v_rel, w[i], h, dt, f, t, s);
    }
  }
  return out;
}

}  // namespace

TEST(ReferenceForces, OneStepMatchesAnAllPairsLoopAtAnyThreadCount) {
  ASSERT_TRUE(law_choices(particle_law()) == kParticleChoices);
  ASSERT_TRUE(law_choices(floor_law()) == kParticleChoices);
  ASSERT_TRUE(law_choices(side_law()) == kSideChoices);
  ASSERT_TRUE(law_choices(plate_law()) == kPlateChoices);
  const int threads_before = omp_get_max_threads();
  for (const int threads : {1, 3, 7}) {
    omp_set_num_threads(threads);
    Simulation sim = make_packing();
    sim.run(30);  // contact histories (springs, rolling springs, sliding) built up
    const Histories histories = capture(sim);
    sim.step();
    const Loads ref = reference_loads(sim, histories);
    const Particles& p = sim.particles();
    std::size_t touching_walls = 0, in_contact = 0;
    double worst = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      const std::size_t s = std::size_t(p.id[i] - 1);
      const double tol = 1e-10 * ref.scale[s];
      const double tol_torque = tol * p.radius[i];
      const double err = norm(p.force[i] - ref.force[s]);
      const double err_torque = norm(p.torque[i] - ref.torque[s]);
      worst = std::max(worst, ref.scale[s] > 0.0 ? std::max(err, err_torque / p.radius[i]) / ref.scale[s] : 0.0);
      in_contact += ref.scale[s] > 0.0 ? 1 : 0;
      EXPECT_LE(err, tol) << "force on particle id " << p.id[i] << " at " << threads << " threads";
      EXPECT_LE(err_torque, tol_torque) << "torque on particle id " << p.id[i] << " at " << threads << " threads";
    }
    for (const auto& [key, h] : histories.walls) touching_walls += h.touching() ? 1 : 0;
    report("{} threads: worst |F - F_ref| / sum|f| = {:.1e} (tol 1e-10), {} particles in contact, {} wall contacts",
           threads, worst, in_contact, touching_walls);
    // The case is the one described: most particles in contact, each wall touched.
    EXPECT_GT(in_contact, p.size() * 8 / 10);
    for (std::uint32_t k = 0; k < sim.walls().size(); ++k) {
      bool touched = false;
      for (const auto& [key, h] : histories.walls) touched = touched || key.second == k;
      EXPECT_TRUE(touched) << "no particle touches wall " << sim.walls()[k].name;
    }
  }
  omp_set_num_threads(threads_before);
}
