// Conservation laws: energy of an elastic frictionless gas, and Newton's third law / linear
// momentum of a dense random packing (periodic, and in a box of walls).
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

Domain periodic_box(double length) {
  Domain d;
  d.lower = {0, 0, 0};
  d.upper = {length, length, length};
  d.periodic[0] = d.periodic[1] = d.periodic[2] = true;
  return d;
}

// n^3 spheres on a cubic lattice of spacing a (first site at a/2), radii and jitter as given,
// random velocities of magnitude up to `speed` per component.
Particles lattice(int n, double a, double r_min, double r_max, double jitter, double speed, std::uint64_t seed) {
  Particles p;
  Rng rng(seed);
  std::int64_t id = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        p.add(id++,
              {a * (i + 0.5) + rng.uniform(-jitter, jitter), a * (j + 0.5) + rng.uniform(-jitter, jitter),
               a * (k + 0.5) + rng.uniform(-jitter, jitter)},
              rng.uniform(r_min, r_max), 2500.0,
              {rng.uniform(-speed, speed), rng.uniform(-speed, speed), rng.uniform(-speed, speed)});
  return p;
}

// Kinetic energy plus the normal springs' energy k_n delta^2 / 2 over touching pairs (minimum image).
double total_energy(const Simulation& sim) {
  const Particles& p = sim.particles();
  const Domain& d = sim.settings().domain;
  const double kn = sim.particle_law().normal_stiffness;
  double e = sim.kinetic_energy();
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double overlap = p.radius[i] + p.radius[j] - norm(d.minimum_image(p.position[i] - p.position[j]));
      if (overlap > 0.0) e += 0.5 * kn * overlap * overlap;
    }
  return e;
}

// The typical contact force: the sum over touching pairs of k_n delta (the spring part of |F_n|).
// Round-off in the force sums is relative to this, not to sum |F_i|, which is small when the
// contacts on each particle nearly balance.
double contact_force_scale(const Simulation& sim) {
  const Particles& p = sim.particles();
  const Domain& d = sim.settings().domain;
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double overlap = p.radius[i] + p.radius[j] - norm(d.minimum_image(p.position[i] - p.position[j]));
      if (overlap > 0.0) s += sim.particle_law().normal_stiffness * overlap;
    }
  return s;
}

Vec3 momentum(const Particles& p) {
  Vec3 m{};
  for (std::size_t i = 0; i < p.size(); ++i) m += p.mass[i] * p.velocity[i];
  return m;
}

double momentum_scale(const Particles& p) {
  double s = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) s += p.mass[i] * norm(p.velocity[i]);
  return s;
}

}  // namespace

// Each test at the default thread count and at 3 threads: a block split with several threads,
// partner shares deferred across blocks, every particle kicked either in the sweep or after it.
class Conservation : public ::testing::TestWithParam<int> {
 protected:
  void SetUp() override {
    threads_before_ = omp_get_max_threads();
    if (GetParam() > 0) omp_set_num_threads(GetParam());
  }
  void TearDown() override { omp_set_num_threads(threads_before_); }

 private:
  int threads_before_ = 1;
};

INSTANTIATE_TEST_SUITE_P(Threads, Conservation, ::testing::Values(0, 3),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return info.param == 0 ? std::string("DefaultThreads") : std::to_string(info.param) + "Threads";
                         });

// 64 spheres (r = 1 mm, 6.5 % solids) at ~1 m/s in a periodic box, e = 1, no friction, no gravity:
// about 100 collisions in 10 ms. Velocity Verlet is symplectic for the springs; what it does not
// conserve is the energy of each contact's onset and end falling inside a step, a random error
// bounded by (w dt)^2 and measured at ~1e-6 of the pair's energy per collision at this dt
// (collision_test). The tolerance 1e-4 relative allows ~100 such errors with margin; a dashpot left on (e = 0.99) would
// lose ~1 % per collision, and a wrong sign or a missing half kick drifts by far more.
TEST_P(Conservation, ElasticFrictionlessGasConservesEnergy) {
  ContactLaw law = frictionless_law(1.0e4, 1.0);
  SimulationSettings s;
  s.domain = periodic_box(0.016);
  s.time_step_fraction = 0.02;
  Simulation sim(lattice(4, 0.004, 0.001, 0.001, 5e-4, 1.0, 11), law, s);
  sim.set_gravity(Vec3{0, 0, 0});
  const double e0 = total_energy(sim);
  const Vec3 p0 = momentum(sim.particles());
  const double p_scale = momentum_scale(sim.particles());
  double worst = 0.0;
  std::size_t max_contacts = 0;
  int collisions = 0;
  std::size_t contacts_before = 0;
  const std::int64_t steps = std::llround(0.01 / sim.time_step());
  for (std::int64_t k = 0; k < steps; ++k) {
    sim.step();
    const std::size_t c = sim.contact_count();
    if (c > contacts_before) collisions += int(c - contacts_before);
    contacts_before = c;
    max_contacts = std::max(max_contacts, c);
    if (k % 100 == 0) worst = std::max(worst, std::fabs(total_energy(sim) / e0 - 1.0));
  }
  worst = std::max(worst, std::fabs(total_energy(sim) / e0 - 1.0));
  report("gas: {} collisions, max |E/E0 - 1| = {:.1e} (tol 1e-4), momentum drift {:.1e} (tol 1e-12)", collisions,
         worst, norm(momentum(sim.particles()) - p0) / p_scale);
  EXPECT_GT(collisions, 30);  // the check means something only if the gas collides
  EXPECT_LT(worst, 1e-4);
  EXPECT_LT(norm(momentum(sim.particles()) - p0) / p_scale, 1e-12);
  // No friction: no torque, no spin.
  EXPECT_EQ(sim.rotational_kinetic_energy(), 0.0);
}

// 125 spheres with radii 0.97-1.01 mm on a 1.96 mm lattice in a periodic box of 5 spacings (a
// jammed packing: overlaps 0.5-3 % of r that persist), with friction and EPSD rolling resistance,
// no gravity. Each pair force is computed once and applied with opposite signs, so the sum of all
// contact forces is zero to round-off: 1e-12 of the summed contact forces (a double sum of a few
// hundred terms errs by ~1e-15 of it). Momentum
// is then constant to round-off over 2000 steps, tolerance 1e-12 of sum m|v|. A force applied to
// one body only, or a partner share gathered twice, breaks both by O(1).
TEST_P(Conservation, DensePackingObeysNewtonsThirdLaw) {
  ContactLaw law = sliding_rolling_law(1.0e4, 0.5, 0.4, 0.3, 0.1);  // mu_s, mu_k, mu_r
  SimulationSettings s;
  s.domain = periodic_box(5 * 0.00196);
  Simulation sim(lattice(5, 0.00196, 0.00097, 0.00101, 1e-5, 0.05, 3), law, s);
  sim.set_gravity(Vec3{0, 0, 0});
  const Vec3 p0 = momentum(sim.particles());
  double worst_force = 0.0, worst_momentum = 0.0;
  std::size_t min_contacts = std::size_t(-1);
  for (int k = 0; k < 2000; ++k) {
    sim.step();
    const Particles& p = sim.particles();
    Vec3 sum{};
    for (std::size_t i = 0; i < p.size(); ++i) sum += p.force[i];
    worst_force = std::max(worst_force, norm(sum) / contact_force_scale(sim));
    worst_momentum = std::max(worst_momentum, norm(momentum(p) - p0) / momentum_scale(p));
    min_contacts = std::min(min_contacts, sim.contact_count());
  }
  report("dense periodic packing: |sum F| / sum k_n delta = {:.1e} (tol 1e-12), momentum drift {:.1e} (tol 1e-12), "
         "contacts >= {}",
         worst_force, worst_momentum, min_contacts);
  EXPECT_GT(min_contacts, 50u);  // the packing stays dense enough for the check to mean something
  EXPECT_LT(worst_force, 1e-12);
  EXPECT_LT(worst_momentum, 1e-12);
}

// The same in a box of walls: the walls' loads are the reactions, so the contact forces on the
// particles plus the loads on the walls sum to zero (round-off). Checks the sign convention of
// Wall::force (load ON the wall) and that every wall contact is counted once.
TEST_P(Conservation, WallLoadsBalanceForcesOnParticles) {
  ContactLaw law = frictionless_law(1.0e4, 0.5);
  law.static_friction = 0.4;
  law.kinetic_friction = 0.3;
  SimulationSettings s;
  s.domain.lower = {-0.001, -0.001, -0.001};
  s.domain.upper = {0.011, 0.011, 0.011};
  Simulation sim(lattice(5, 0.002, 0.00097, 0.00101, 1e-5, 0.05, 5), law, s);
  sim.set_gravity(Vec3{0, 0, 0});
  const double lo = 0.00005, hi = 0.00995;  // m: walls pressing on the outer layer (overlaps ~5 % of r)
  sim.add_wall(Wall::plane("x-", {lo, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x+", {hi, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y-", {0, lo, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y+", {0, hi, 0}, {0, -1, 0}, law));
  sim.add_wall(Wall::rectangle("z-", {0.005, 0.005, lo}, {1, 0, 0}, 0.006, {0, 1, 0}, 0.006, law));
  sim.add_wall(Wall::rectangle("z+", {0.005, 0.005, hi}, {0, 1, 0}, 0.006, {1, 0, 0}, 0.006, law));
  double worst = 0.0, wall_load = 0.0;
  for (int k = 0; k < 1000; ++k) {
    sim.step();
    const Particles& p = sim.particles();
    Vec3 sum{};
    double magnitude = contact_force_scale(sim);
    for (std::size_t i = 0; i < p.size(); ++i) sum += p.force[i];
    for (const Wall& w : sim.walls()) {
      sum += w.force;
      magnitude += norm(w.force);
      wall_load = std::max(wall_load, norm(w.force));
    }
    worst = std::max(worst, norm(sum) / magnitude);
  }
  report("packing in walls: |sum F_particles + sum F_walls| / (sum k_n delta + sum |F_wall|) = {:.1e} (tol 1e-12)",
         worst);
  EXPECT_GT(wall_load, 0.0);
  EXPECT_LT(worst, 1e-12);
}
