// The first half kick and drift inside the contact sweep (Simulation::step, contact_sweep.cpp):
// when the last step's second half kick forecast the displacements and they call for no list
// rebuild, each particle is kicked and drifted just before the sweep first reads it instead of
// in a pass of its own. It must give the same bits as the pass: same expressions (kick_and_drift),
// every particle moved before any pair, wall or kick reads it (also across thread blocks), and the
// rebuilds on the same steps (the forecast equals the displacement the drift then gives).
// The reference is the same run with the forecast dropped after every step (set_gravity with the
// same gravity does that: a change between steps must drop it), which drifts in the pass.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <functional>

#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

class ThreadCount {
 public:
  explicit ThreadCount(int n) : saved_(omp_get_max_threads()) { omp_set_num_threads(n); }
  ~ThreadCount() { omp_set_num_threads(saved_); }

 private:
  int saved_;
};

struct Outcome {
  std::vector<std::int64_t> id;
  std::vector<Vec3> position, velocity, spin, force;
  std::vector<Vec3> wall_force;
  std::int64_t rebuilds;
  std::int64_t drifts_in_sweep;
};

enum class Gravity { constant, ramp };

// 300 polydisperse spheres thrown down into a box of walls (with friction and EPSD rolling), with
// a moving wall, 1200 steps: they fall, collide and pile up, so the lists are rebuilt many times.
Outcome throw_down(int threads, bool drift_in_pass, Gravity gravity) {
  ThreadCount guard(threads);
  ContactLaw law = frictionless_law(1.0e4, 0.3);
  law.static_friction = 0.5;
  law.kinetic_friction = 0.4;
  law.rolling_friction = 0.1;
  law.rolling_model = RollingModel::elastic_plastic;
  Particles p;
  Rng rng(7);
  std::int64_t id = 0;
  for (int i = 0; i < 10; ++i)
    for (int j = 0; j < 6; ++j)
      for (int k = 0; k < 5; ++k)
        p.add(id++, {-0.0104 + 0.0023 * i, -0.0058 + 0.0023 * j, 0.00116 + 0.0023 * k}, rng.uniform(0.0007, 0.00115),
              2500.0, {rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-0.6, 0.0)});
  SimulationSettings s;
  s.domain.lower = {-0.013, -0.008, -0.001};
  s.domain.upper = {0.013, 0.008, 0.04};
  s.time_step_fraction = 0.3;
  Simulation sim(std::move(p), law, s);
  if (gravity == Gravity::constant)
    sim.set_gravity(Vec3{0, 0, -100.0});
  else  // a spin-up: the gravity changes every step of the first half
    sim.set_gravity([](double t) { return Vec3{0, 0, -100.0 * std::min(1.0, t / 0.006)}; });
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.add_wall(Wall::plane("x-", {-0.0118, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x+", {0.0118, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y-", {0, -0.0070, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y+", {0, 0.0070, 0}, {0, -1, 0}, law));
  sim.set_wall_velocity(sim.find_wall("x+"), Vec3{-0.05, 0, 0});  // squeezes the pile: wall-driven rebuilds too
  const std::function<Vec3(double)> ramp = [](double t) { return Vec3{0, 0, -100.0 * std::min(1.0, t / 0.006)}; };
  for (int step = 0; step < 1200; ++step) {
    sim.step();
    if (drift_in_pass) {  // the same gravity, set anew: drops the forecast
      if (gravity == Gravity::constant)
        sim.set_gravity(sim.gravity());
      else
        sim.set_gravity(ramp);
    }
  }
  EXPECT_GT(sim.contact_count(), 50u);  // the run exercises the contact kernels
  EXPECT_GT(sim.stats().rebuilds, 10);    // and the rebuild decision
  const Particles& q = sim.particles();
  Outcome out{q.id, q.position, q.velocity, q.angular_velocity, q.force, {}, sim.stats().rebuilds,
              sim.stats().drifts_in_sweep};
  for (const Wall& w : sim.walls()) out.wall_force.push_back(w.force);
  return out;
}

// a: the sweep drifted (on every step without a rebuild), b: the pass did (on every step).
void expect_same_bits(const Outcome& a, const Outcome& b, const std::string& what) {
  EXPECT_EQ(a.drifts_in_sweep, 1200 - a.rebuilds) << what;
  EXPECT_EQ(b.drifts_in_sweep, 0) << what;
  ASSERT_EQ(a.id, b.id) << what << ": particle order differs";
  EXPECT_EQ(a.rebuilds, b.rebuilds) << what << ": rebuilds";
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i)
    differ += !(a.position[i] == b.position[i] && a.velocity[i] == b.velocity[i] && a.spin[i] == b.spin[i] &&
                a.force[i] == b.force[i]);
  EXPECT_EQ(differ, 0u) << what << ": particles whose state is not bitwise equal";
  for (std::size_t k = 0; k < a.wall_force.size(); ++k) EXPECT_TRUE(a.wall_force[k] == b.wall_force[k]) << what << ": wall " << k;
}

}  // namespace

class SweepDrift : public ::testing::TestWithParam<int> {};

TEST_P(SweepDrift, SameBitsAsTheDriftPass) {
  const int threads = GetParam();
  expect_same_bits(throw_down(threads, false, Gravity::constant), throw_down(threads, true, Gravity::constant),
                   fmt::format("{} threads, constant gravity", threads));
}

TEST_P(SweepDrift, SameBitsAsTheDriftPassWhileGravityChanges) {
  const int threads = GetParam();
  expect_same_bits(throw_down(threads, false, Gravity::ramp), throw_down(threads, true, Gravity::ramp),
                   fmt::format("{} threads, gravity ramp", threads));
}

INSTANTIATE_TEST_SUITE_P(Threads, SweepDrift, ::testing::Values(1, 2, 3));
