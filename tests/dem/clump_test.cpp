// Rigid clumps in the engine (issue 39): analytic cases (a dimer at rest on a floor, rolling across
// an incline and sliding along it), properties (an elastic impact of two clumps conserves momentum,
// angular momentum and energy), the members' forces against an all-pairs loop at 1, 3 and 7
// threads, and the runs a clump cannot be part of.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <algorithm>
#include <map>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

#include "core/errors.hpp"
#include "dem/contact/law.hpp"
#include "dem/rigid/clump_shapes.hpp"
#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kDensity = 2500.0;     // kg/m^3
constexpr double kDiameter = 0.002;     // m, volume-equivalent
constexpr double kStiffness = 1.0e4;    // N/m
constexpr double kG = 9.81;             // m/s^2

ClumpTemplate dimer(double aspect = 1.5) {
  return make_clump_template(dimer_members(aspect), "dimer").scaled_to(kDiameter);
}

ContactLaw frictional_law(double mu_s, double mu_k, double restitution = 0.5) {
  ContactLaw law = frictionless_law(kStiffness, restitution);
  law.static_friction = mu_s;
  law.kinetic_friction = mu_k;
  return law;
}

SimulationSettings settings(double fraction = 0.1) {
  SimulationSettings s;
  s.domain = box(0.2);
  s.time_step_fraction = fraction;
  return s;
}

// One body of `shape` at rest, its centre at `x`, in a run of its own.
Simulation one_body(const ClumpTemplate& shape, const Vec3& x, const ContactLaw& law, const Quaternion& q = {}) {
  Particles p;
  RigidBodies bodies;
  add_rigid_body(bodies, p, 1, 1, shape, kDensity, x, q);
  return Simulation(std::move(p), law, settings(), std::move(bodies));
}

Vec3 total_momentum(const RigidBodies& b) {
  Vec3 m{};
  for (std::size_t k = 0; k < b.size(); ++k) m += b.mass[k] * b.velocity[k];
  return m;
}

Vec3 total_angular_momentum(const RigidBodies& b) {  // about the origin
  Vec3 l{};
  for (std::size_t k = 0; k < b.size(); ++k) l += b.angular_momentum[k] + cross(b.position[k], b.mass[k] * b.velocity[k]);
  return l;
}

}  // namespace

// A dimer lying on a floor, its axis horizontal: by symmetry each sphere carries half the weight,
// so each overlaps by m g / (2 k_n) and the floor carries m g. The dimer starts 1 um above its
// rest height and settles under the dashpot (e = 0.5: the normal oscillation decays by ~e per
// period, ~250 periods in 0.05 s). Tolerances: 1e-6 of the weight and of the overlap, the
// residue of the decayed oscillation and of the tangential springs (nothing loads them but
// round-off).
TEST(ClumpRest, DimerOnAFloorCarriesHalfItsWeightOnEachSphere) {
  const ClumpTemplate shape = dimer();
  const double r = shape.members[0].radius;
  Simulation sim = one_body(shape, {0, 0, r + 1e-6}, frictional_law(0.5, 0.5));
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictional_law(0.5, 0.5)));
  sim.run(std::int64_t(0.05 / sim.time_step()));
  const double weight = sim.bodies().mass[0] * kG;
  EXPECT_NEAR(-sim.wall(0).force.z, weight, 1e-6 * weight);  // the load on the floor points down
  const double overlap = weight / (2.0 * kStiffness);
  for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(r - sim.particles().position[i].z, overlap, 1e-6 * overlap);
  EXPECT_LT(norm(sim.bodies().velocity[0]), 1e-9);
  EXPECT_LT(norm(sim.bodies().angular_velocity(0)), 1e-6);
  report("floor load {:.6e} N vs weight {:.6e} N; overlap {:.6e} vs {:.6e} m", -sim.wall(0).force.z, weight,
         r - sim.particles().position[0].z, overlap);
}

namespace {

// A dimer resting on a floor while gravity tilts from vertical to atan(slope) over kRamp towards
// `downhill` (a unit vector in the floor's plane), so that the contacts load quasi-statically
// (friction_test.cpp explains the ramp); its centre's acceleration along `downhill` is measured
// over [kRamp + 10 ms, kRamp + 30 ms], and its spin about the dimer's axis at the end.
constexpr double kRamp = 0.01;  // s
struct InclineRun {
  double acceleration;  // m/s^2, along downhill
  double speed;         // m/s, along downhill, at the end
  double spin;          // rad/s, about the dimer's axis (x) at the end
  double mass, axial_inertia, radius;
};
InclineRun dimer_on_incline(const Vec3& downhill, double slope, double mu_s, double mu_k) {
  const ClumpTemplate shape = dimer();
  const double r = shape.members[0].radius;
  const double m = kDensity * shape.volume;
  const ContactLaw law = frictional_law(mu_s, mu_k);
  Simulation sim = one_body(shape, {0, 0, r - m * kG / (2.0 * kStiffness)}, law);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  const double angle = std::atan(slope);
  sim.set_gravity([angle, downhill](double t) {
    const double a = angle * std::min(1.0, t / kRamp);
    return kG * std::sin(a) * downhill + Vec3{0.0, 0.0, -kG * std::cos(a)};
  });
  const double dt = sim.time_step();
  const auto steps_to = [&](double t) { return std::int64_t(std::llround(t / dt)); };
  sim.run(steps_to(kRamp + 0.01));
  const double t1 = sim.time(), v1 = dot(sim.bodies().velocity[0], downhill);
  sim.run(steps_to(0.02));
  const double t2 = sim.time(), v2 = dot(sim.bodies().velocity[0], downhill);
  return {(v2 - v1) / (t2 - t1), v2, sim.bodies().angular_velocity(0).x, sim.bodies().mass[0],
          sim.bodies().principal_inertia[0].x, r};
}

}  // namespace

// Across the slope (the dimer's axis x horizontal, downhill +y) the dimer rolls on its two spheres
// about its own axis, each contact a distance r below the axis: without slip,
// a = g sin / (1 + I_x / (m r^2)) with I_x the union's axial moment, and the spin -v / r about x.
// Static friction suffices where mu_s >= tan I_x / (I_x + m r^2) (~0.1 here: mu_s = 0.8).
// Tolerance 1e-3: the tangential springs' compliance and the decayed oscillation of the ramp
// (measured ~1e-5); using the sum of the spheres' moments, or a sphere's 2/5 m r^2, for I_x is off
// by several per cent, a slip by tens.
TEST(ClumpIncline, DimerAcrossTheSlopeRollsAtTheRigidBodyRate) {
  const double slope = 0.3, angle = std::atan(slope);
  const InclineRun run = dimer_on_incline({0, 1, 0}, slope, 0.8, 0.8);
  const double expected = kG * std::sin(angle) / (1.0 + run.axial_inertia / (run.mass * run.radius * run.radius));
  EXPECT_NEAR(run.acceleration, expected, 1e-3 * expected);
  EXPECT_NEAR(run.spin, -run.speed / run.radius, 1e-3 * run.speed / run.radius);
  report("rolling: a {:.6f} vs g sin / (1 + I/(m r^2)) = {:.6f} m/s^2 (rel {:.1e}); spin {:.4f} vs -v/r {:.4f} rad/s",
         run.acceleration, expected, std::fabs(run.acceleration / expected - 1.0), run.spin, -run.speed / run.radius);
}

// Along the slope (downhill +x, the dimer's axis) it cannot roll: gravity has no moment about its
// axis, and a roll about y would lift a sphere. Above the static limit it slides as a block:
// a = g (sin - mu_k cos), whatever the split of the normal load between its spheres (each slides
// at mu_k of its own). Tolerance 1e-6: the decayed normal and pitching oscillations; mu_s in
// place of mu_k is off by 30 %.
TEST(ClumpIncline, DimerAlongTheSlopeSlidesAtTheKineticRate) {
  const double slope = 0.6, angle = std::atan(slope), mu_k = 0.3;
  const InclineRun run = dimer_on_incline({1, 0, 0}, slope, 0.4, mu_k);
  const double expected = kG * (std::sin(angle) - mu_k * std::cos(angle));
  EXPECT_NEAR(run.acceleration, expected, 1e-6 * expected);
  report("sliding: a {:.8f} vs g (sin - mu_k cos) = {:.8f} m/s^2 (rel {:.1e})", run.acceleration, expected,
         std::fabs(run.acceleration / expected - 1.0));
}

// Two irregular clumps meet off centre, spinning, in free space, with an elastic law (e = 1, no
// dashpot) and friction: the pair forces are equal and opposite at one contact point, so the
// total momentum and the total angular momentum about the origin are conserved to round-off
// (tolerance 1e-12 of their scale: ~1e4 steps of ~1e-16 each). Energy: friction dissipates, so
// frictionless here, and the elastic energy is back in motion after the impact; velocity Verlet's
// energy error is O(dt^2) and returns after the contact: tolerance 1e-4 of the kinetic energy.
TEST(ClumpCollision, ElasticImpactConservesMomentumAngularMomentumAndEnergy) {
  for (const double mu : {0.0, 0.5}) {
    const ClumpTemplate shape = make_clump_template(sub_angular_members(6, 0.6, 1.4, 0.8), "grain").scaled_to(kDiameter);
    Particles p;
    RigidBodies bodies;
    add_rigid_body(bodies, p, 1, 1, shape, kDensity, {-0.002, 0.0003, 0.0}, Quaternion::about_axis({0, 0, 1}, 0.3),
                   {0.2, 0, 0}, {0, 40, 10});
    add_rigid_body(bodies, p, 2, 100, shape, kDensity, {0.002, -0.0002, 0.0001},
                   Quaternion::about_axis({0.6, 0, 0.8}, 1.1), {-0.2, 0.01, 0}, {30, 0, -20});
    ContactLaw law = frictional_law(mu, mu, 1.0);
    SimulationSettings s = settings(0.05);
    Simulation sim(std::move(p), law, s, std::move(bodies));
    sim.set_gravity(Vec3{});
    const Vec3 momentum = total_momentum(sim.bodies()), angular = total_angular_momentum(sim.bodies());
    const double energy = sim.kinetic_energy();
    double closest = 1e9;
    int steps_in_contact = 0;
    for (int k = 0; k < int(0.007 / sim.time_step()); ++k) {
      sim.step();
      steps_in_contact += sim.contact_count() > 0 ? 1 : 0;
      closest = std::min(closest, norm(sim.bodies().position[0] - sim.bodies().position[1]));
    }
    ASSERT_GT(steps_in_contact, 10) << "the clumps must meet (mu " << mu << ")";
    EXPECT_EQ(sim.contact_count(), 0u) << "and part again";
    const double p_scale = sim.bodies().mass[0] * 0.2, l_scale = p_scale * 0.002;
    EXPECT_LT(norm(total_momentum(sim.bodies()) - momentum), 1e-12 * p_scale) << "mu " << mu;
    EXPECT_LT(norm(total_angular_momentum(sim.bodies()) - angular), 1e-12 * l_scale) << "mu " << mu;
    if (mu == 0.0) {
      EXPECT_NEAR(sim.kinetic_energy(), energy, 1e-4 * energy);
    }
    if (mu > 0.0) {
      EXPECT_LE(sim.kinetic_energy(), energy * (1.0 + 1e-4)) << "friction creates no energy";
    }
    report("mu {}: {} steps in contact, momentum error {:.1e}, angular {:.1e}, energy {:.6e} -> {:.6e} J", mu,
           steps_in_contact, norm(total_momentum(sim.bodies()) - momentum) / p_scale,
           norm(total_angular_momentum(sim.bodies()) - angular) / l_scale, energy, sim.kinetic_energy());
  }
}

namespace {

// A loose heap of irregular clumps over a floor, each member a particle with a stable id.
Simulation clump_heap() {
  const ClumpTemplate shape = make_clump_template(sub_angular_members(5, 0.6, 1.3, 0.9), "grain").scaled_to(kDiameter);
  Particles p;
  RigidBodies bodies;
  std::mt19937_64 rng(2026);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::int64_t member_id = 1;
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k) {
        Vec3 axis{u(rng), u(rng), u(rng)};
        const Quaternion q = Quaternion::about_axis(axis / norm(axis), 3.2 * u(rng));
        const Vec3 x{0.0023 * i, 0.0023 * j, 0.0012 + 0.0023 * k};
        add_rigid_body(bodies, p, 1 + i * 16 + j * 4 + k, member_id, shape, kDensity, x, q,
                       {0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng)}, {20 * u(rng), 20 * u(rng), 20 * u(rng)});
        member_id += std::int64_t(shape.members.size());
      }
  SimulationSettings s = settings(0.2);
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.03, 0.03, 0.03};
  s.max_overlap_fraction = 0.9;
  Simulation sim(std::move(p), frictional_law(0.5, 0.4), s, std::move(bodies));
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictional_law(0.6, 0.6)));
  return sim;
}

}  // namespace

// The members' forces and torques after one step against an O(M^2) loop over every two members of
// different bodies and every member and the floor, calling the law's sub-models directly (as
// reference_force_test.cpp, whose header explains the reading of the state: the half-step
// velocities recovered from the end of the step, the histories of the step before by ids). Here
// the bodies' half-step velocity and angular momentum are recovered, and each member's from them.
// Then each body's force and torque against the sum over its members. Tolerance as there: 1e-10 x
// the sum of the magnitudes of a member's contact forces. A pair of one body's members listed would
// add a force of the order of the contact forces (their overlap is of the member's radius).
TEST(ClumpForces, MemberForcesMatchAnAllPairsLoopAtAnyThreadCount) {
  const int threads_before = omp_get_max_threads();
  constexpr LawChoices kChoices{};
  for (const int threads : {1, 3, 7}) {
    omp_set_num_threads(threads);
    Simulation sim = clump_heap();
    ASSERT_TRUE(law_choices(sim.particle_law()) == kChoices);
    sim.run(40);
    std::map<std::pair<std::int64_t, std::int64_t>, ContactHistory> pair_histories;
    std::map<std::int64_t, ContactHistory> floor_histories;
    {
      const Particles& p = sim.particles();
      const PairList pairs = sim.pairs();
      for (std::uint32_t i = 0; i + 1 < pairs.first.size(); ++i)
        for (std::uint32_t k = pairs.first[i]; k < pairs.first[i + 1]; ++k)
          if (pairs.history[k].touching()) pair_histories[{p.id[i], p.id[pairs.partner[k]]}] = pairs.history[k];
      const WallList& walls = sim.wall_candidates();
      for (std::uint32_t i = 0; i + 1 < walls.first.size(); ++i)
        for (std::uint32_t k = walls.first[i]; k < walls.first[i + 1]; ++k)
          if (walls.history[k].touching()) floor_histories[p.id[i]] = walls.history[k];
    }
    sim.step();
    const Particles& p = sim.particles();
    const RigidBodies& bodies = sim.bodies();
    const double dt = sim.time_step(), half = 0.5 * dt;
    const Vec3 g = sim.gravity();
    // The state the force pass read: each member's half-step velocity and spin from its body's.
    const std::size_t n = p.size();
    std::vector<Vec3> v(n), w(n);
    std::vector<std::size_t> body_of(n);
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const Vec3 vb = bodies.velocity[b] - half * (bodies.force[b] / bodies.mass[b] + g);
      const Vec3 L = bodies.angular_momentum[b] - half * bodies.torque[b];
      const Vec3 Lb = rotate_inverse(bodies.orientation[b], L);
      const Vec3& I = bodies.principal_inertia[b];
      const Vec3 wb = rotate(bodies.orientation[b], Vec3{Lb.x / I.x, Lb.y / I.y, Lb.z / I.z});
      for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
        const std::uint32_t i = bodies.member_particle[m];
        v[i] = vb + cross(wb, bodies.member_arm(b, m));
        w[i] = wb;
        body_of[i] = b;
      }
    }
    std::vector<Vec3> force(n), torque(n);
    std::vector<double> scale(n, 0.0);
    const LawParams law = law_params(sim.particle_law(), sim.particle_law());
    std::size_t between_bodies = 0;
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = i + 1; j < n; ++j) {
        if (body_of[i] == body_of[j]) continue;
        const Vec3 d = p.position[i] - p.position[j];
        const double dist = norm(d), reach = p.radius[i] + p.radius[j];
        if (!(dist < reach)) continue;
        ++between_bodies;
        const Vec3 normal = d / dist;
        const double overlap = reach - dist;
        const ContactBodies cb = reduce_bodies<kChoices, SecondBody::sphere>(
            Body{p.mass[i], p.radius[i], p.inv_inertia[i]}, Body{p.mass[j], p.radius[j], p.inv_inertia[j]}, overlap, dist);
        ContactHistory h{};
        if (auto it = pair_histories.find({p.id[i], p.id[j]}); it != pair_histories.end()) h = it->second;
        if (auto it = pair_histories.find({p.id[j], p.id[i]}); it != pair_histories.end()) {
          h = it->second;
          h.tangential_spring = -h.tangential_spring;
        }
        const ContactForce cf = ContactEvaluator<kChoices>::evaluate(law, cb, normal, overlap, v[i] - v[j], w[i], w[j], h, dt);
        const ContactTorques t = contact_torques(cf, cb, normal);
        force[i] += cf.force;
        force[j] -= cf.force;
        torque[i] += t.on_i;
        torque[j] += t.on_j;
        scale[i] += norm(cf.force);
        scale[j] += norm(cf.force);
      }
    const Wall& floor = sim.wall(0);
    const LawParams floor_law = law_params(floor.law, sim.particle_law());
    std::size_t on_floor = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const WallProximity near = wall_proximity(floor, p.position[i]);
      if (!(near.distance < p.radius[i])) continue;
      ++on_floor;
      const double overlap = p.radius[i] - near.distance;
      const ContactBodies cb = reduce_bodies<kChoices, SecondBody::wall>(Body{p.mass[i], p.radius[i], p.inv_inertia[i]},
                                                                         Body{0.0, 0.0, 0.0}, overlap, near.distance);
      ContactHistory h{};
      if (auto it = floor_histories.find(p.id[i]); it != floor_histories.end()) h = it->second;
      const ContactForce cf =
          ContactEvaluator<kChoices>::evaluate(floor_law, cb, near.normal, overlap, v[i], w[i], Vec3{}, h, dt);
      force[i] += cf.force;
      torque[i] += contact_torques(cf, cb, near.normal).on_i;
      scale[i] += norm(cf.force);
    }
    ASSERT_GT(between_bodies, 15u) << "a heap in contact";
    ASSERT_GT(on_floor, 2u);
    for (std::size_t i = 0; i < n; ++i) {
      EXPECT_LE(norm(p.force[i] - force[i]), 1e-10 * scale[i]) << "member id " << p.id[i] << ", " << threads << " threads";
      EXPECT_LE(norm(p.torque[i] - torque[i]), 1e-10 * scale[i] * p.radius[i]) << "member id " << p.id[i];
    }
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      Vec3 f{}, t{};
      double s = 0.0;
      for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
        const std::uint32_t i = bodies.member_particle[m];
        f += force[i];
        t += cross(p.position[i] - bodies.position[b], force[i]) + torque[i];
        s += scale[i];
      }
      EXPECT_LE(norm(bodies.force[b] - f), 1e-10 * s) << "body " << bodies.id[b];
      EXPECT_LE(norm(bodies.torque[b] - t), 1e-10 * s * kDiameter) << "body " << bodies.id[b];
    }
    report("{} threads: {} member pairs in contact between bodies, {} on the floor", threads, between_bodies, on_floor);
  }
  omp_set_num_threads(threads_before);
}

// A run with bodies takes bodies only, on one process, with bounded axes: each refused by name.
TEST(ClumpGuards, WhatARunWithBodiesRefuses) {
  Simulation sim = one_body(dimer(), {0, 0, 0.01}, frictional_law(0.5, 0.5));
  EXPECT_THROW(sim.add_particle(99, {0, 0, 0.02}, 0.001, kDensity), InputError);
  EXPECT_THROW(sim.remove_particles({0}), InputError);
  sim.add_body(2, 10, dimer(1.2), kDensity, {0.01, 0, 0.01}, {});
  EXPECT_EQ(sim.bodies().size(), 2u);
  sim.step();
  EXPECT_EQ(sim.particles().size(), 4u);

  Particles spheres;
  spheres.add(1, {0, 0, 0}, 0.001, kDensity);
  Simulation of_spheres(std::move(spheres), frictional_law(0.5, 0.5), settings());
  EXPECT_THROW(of_spheres.add_body(2, 10, dimer(), kDensity, {0.01, 0, 0}, {}), InputError);

  SimulationSettings periodic = settings();
  periodic.domain.periodic[1] = true;
  Particles p;
  RigidBodies bodies;
  add_rigid_body(bodies, p, 1, 1, dimer(), kDensity, {}, {});
  try {
    Simulation refused(std::move(p), frictional_law(0.5, 0.5), periodic, std::move(bodies));
    FAIL() << "a periodic axis with bodies must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the y axis is periodic"), std::string::npos) << e.what();
  }
}

// The particles permuted (as the cell sort does at a rebuild): the bodies follow without a
// search and are put in the order of their first member, each body's state and members moving
// with it. Checked against the definitions: every member found by its id (locate_members, the
// search), the keys ascending, and each body's values equal to the same body's (by id) before.
TEST(ClumpOrder, BodiesFollowAPermutationOfTheParticlesIntoTheirFirstMembersOrder) {
  Simulation sim = clump_heap();
  sim.run(5);  // arms and spins current, as at a rebuild within a step
  Particles p = sim.particles();
  RigidBodies bodies = sim.bodies();
  ASSERT_EQ(bodies.arm.size(), bodies.member_count());
  const RigidBodies before = bodies;
  std::vector<std::uint32_t> order(p.size());
  std::iota(order.begin(), order.end(), 0u);
  std::shuffle(order.begin(), order.end(), std::mt19937_64(7));
  p.permute(order);
  bodies.follow_particle_permutation(order);

  RigidBodies searched = bodies;
  searched.locate_members(p.id);
  EXPECT_EQ(bodies.member_particle, searched.member_particle);
  EXPECT_EQ(bodies.body_of_particle, searched.body_of_particle);
  std::uint32_t last_key = 0;
  std::map<std::int64_t, std::size_t> was;
  for (std::size_t b = 0; b < before.size(); ++b) was[before.id[b]] = b;
  ASSERT_EQ(bodies.size(), before.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    std::uint32_t key = ~0u;
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m)
      key = std::min(key, bodies.member_particle[m]);
    if (b > 0) {
      EXPECT_GT(key, last_key) << "body " << b;
    }
    last_key = key;
    const std::size_t a = was.at(bodies.id[b]);
    EXPECT_EQ(bodies.mass[b], before.mass[a]);
    EXPECT_EQ(bodies.volume[b], before.volume[a]);
    EXPECT_EQ(bodies.position[b], before.position[a]);
    EXPECT_EQ(bodies.velocity[b], before.velocity[a]);
    const Quaternion& q = bodies.orientation[b];
    const Quaternion& q0 = before.orientation[a];
    EXPECT_TRUE(q.w == q0.w && q.x == q0.x && q.y == q0.y && q.z == q0.z) << "body " << bodies.id[b];
    EXPECT_EQ(bodies.angular_momentum[b], before.angular_momentum[a]);
    EXPECT_EQ(bodies.force[b], before.force[a]);
    EXPECT_EQ(bodies.torque[b], before.torque[a]);
    EXPECT_EQ(bodies.inverse_inertia[b], before.inverse_inertia[a]);
    EXPECT_EQ(bodies.principal_inertia[b], before.principal_inertia[a]);
    ASSERT_EQ(bodies.first_member[b + 1] - bodies.first_member[b], before.first_member[a + 1] - before.first_member[a]);
    for (std::uint32_t k = 0; k < bodies.first_member[b + 1] - bodies.first_member[b]; ++k) {
      const std::uint32_t m = bodies.first_member[b] + k, old = before.first_member[a] + k;
      EXPECT_EQ(bodies.member_id[m], before.member_id[old]);
      EXPECT_EQ(bodies.member_offset[m], before.member_offset[old]);
      EXPECT_EQ(bodies.arm[m], before.arm[old]);
      EXPECT_EQ(p.id[bodies.member_particle[m]], bodies.member_id[m]);
    }
  }
}
