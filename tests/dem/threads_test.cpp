// Reproducibility across OpenMP thread counts. Each thread owns a block of particles and adds
// the partner shares of pairs reaching into a later block after the loop (simulation.cpp), so
// another thread count changes the order of a few additions: trajectories agree to round-off
// across thread counts, and are bitwise identical for a given count. Wall loads are summed per
// thread, then in thread order: likewise.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>

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

struct Snapshot {
  std::vector<std::int64_t> id;
  std::vector<Vec3> position, velocity, spin;
  std::vector<Vec3> wall_force;
  std::int64_t rebuilds;
};

// 192 polydisperse spheres thrown down into a box of walls, with friction and EPSD rolling
// resistance, 1500 steps (they hit the floor and each other: hundreds of contacts).
Snapshot settle(int threads) {
  ThreadCount guard(threads);
  ContactLaw law = sliding_rolling_law(1.0e4, 0.3, 0.5, 0.4, 0.1);  // mu_s, mu_k, mu_r
  Particles p;
  Rng rng(21);
  std::int64_t id = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 3; ++k)
        p.add(id++, {-0.00805 + 0.0023 * i, -0.00805 + 0.0023 * j, 0.00116 + 0.0023 * k}, rng.uniform(0.0007, 0.00115),
              2500.0, {rng.uniform(-0.2, 0.2), rng.uniform(-0.2, 0.2), rng.uniform(-0.6, 0.0)});
  SimulationSettings s;
  s.domain.lower = {-0.012, -0.012, -0.001};
  s.domain.upper = {0.012, 0.012, 0.03};
  s.time_step_fraction = 0.3;
  Simulation sim(std::move(p), law, s);
  sim.set_gravity(Vec3{0, 0, -100.0});  // fast settling
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.add_wall(Wall::plane("x-", {-0.0093, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x+", {0.0093, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y-", {0, -0.0093, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y+", {0, 0.0093, 0}, {0, -1, 0}, law));
  sim.run(1500);
  EXPECT_GT(sim.contact_count(), 100u);  // the run exercises the contact kernels
  const Particles& q = sim.particles();
  Snapshot snap{q.id, q.position, q.velocity, q.angular_velocity, {}, sim.stats().rebuilds};
  for (const Wall& w : sim.walls()) snap.wall_force.push_back(w.force);
  return snap;
}

void expect_bitwise_equal_particles(const Snapshot& a, const Snapshot& b, const char* what) {
  ASSERT_EQ(a.id, b.id) << what << ": particle order differs";
  EXPECT_EQ(a.rebuilds, b.rebuilds) << what;
  std::size_t differ = 0;
  for (std::size_t i = 0; i < a.id.size(); ++i)
    differ += !(a.position[i] == b.position[i] && a.velocity[i] == b.velocity[i] && a.spin[i] == b.spin[i]);
  EXPECT_EQ(differ, 0u) << what << ": particles whose state is not bitwise equal";
}

}  // namespace

// Round-off (1e-16 relative) in the order of additions grows through the collisions of a
// settling bed, but over these 1500 steps it stays far below any physical scale: positions must
// agree within 1e-9 of a radius (1e-12 m) and wall loads within 1e-9 of the floor load. A real
// thread-safety fault (a lost or doubled force) moves particles by many orders more.
TEST(Threads, OneAndTwoThreadsAgreeToRoundOff) {
  const Snapshot one = settle(1);
  const Snapshot two = settle(2);
  ASSERT_EQ(one.id, two.id) << "particle order differs";
  EXPECT_EQ(one.rebuilds, two.rebuilds);
  double worst_position = 0.0;
  for (std::size_t i = 0; i < one.id.size(); ++i)
    worst_position = std::max(worst_position, norm(one.position[i] - two.position[i]));
  report("threads: largest position difference 1 vs 2 threads {:.1e} m (tol 1e-12 m)", worst_position);
  EXPECT_LT(worst_position, 1e-12);
  const double scale = norm(one.wall_force[0]);
  ASSERT_GT(scale, 0.0);
  double worst = 0.0;
  for (std::size_t k = 0; k < one.wall_force.size(); ++k) worst = std::max(worst, norm(one.wall_force[k] - two.wall_force[k]));
  report("threads: wall load difference 1 vs 2 threads {:.1e} of the floor load (tol 1e-9)", worst / scale);
  EXPECT_LT(worst, 1e-9 * scale);
}

TEST(Threads, SameThreadCountIsBitwiseRepeatable) {
  const Snapshot a = settle(2);
  const Snapshot b = settle(2);
  expect_bitwise_equal_particles(a, b, "2 threads twice");
  for (std::size_t k = 0; k < a.wall_force.size(); ++k) EXPECT_TRUE(a.wall_force[k] == b.wall_force[k]) << "wall " << k;
}
