// Contacts that cross a sub-domain boundary keep their history. A floor moving at a constant
// velocity along x carries what rests on it across the boundary between rank 0 and rank 1 (x = 0
// here), with gravity tilted so that each contact holds a steady tangential (or rolling) spring:
//
// - a block (a sphere that does not rotate) carried by the floor, gravity (1, 0, -9.81) m/s^2:
//   its wall contact sticks with a tangential force m g_x (mu = 0.5 > g_x / g_z);
// - two such blocks stacked, the upper one offset by 0.2 mm along x: the pair's contact sticks
//   too, and for ~4 ms its two particles are on different ranks (the pair computed by the owner
//   of the lower id, the other a ghost there); the pair's history migrates with that particle;
// - a sphere free to rotate, gravity (0.5, 0, -9.81): the EPSD rolling spring holds the torque
//   m g_x R of the friction force (mu_r = 0.1 > g_x / g_z), so it does not roll.
//
// Each step, every particle's force and torque on R ranks equal the one-process run's to 1e-9 of
// their magnitude (the same contacts in the same order: round-off only, ~1e-15). A history lost
// at the boundary restarts the spring from zero: the tangential force (or rolling torque) drops
// to ~0 at the crossing, which also fails the continuity check: from one step to the next the
// steady force changes by less than 1e-6 of itself.
#include <gtest/gtest.h>
#include <omp.h>

#include "mpi_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kRadius = 1e-3;       // m
constexpr double kDensity = 2500.0;    // kg/m^3
constexpr double kFloorSpeed = 0.05;   // m/s along x
constexpr double kStart = -0.6e-3;     // m, the lower block's x at the start: it reaches x = 0 after 12 ms

ContactLaw sticky_law(bool rolling) {
  ContactLaw law;
  law.normal_stiffness = 1.0e4;
  law.tangential_stiffness = 0.5e4;
  law.restitution = 0.2;
  law.static_friction = law.kinetic_friction = 0.5;
  law.rolling_friction = rolling ? 0.1 : 0.0;
  law.rolling_model = rolling ? RollingModel::elastic_plastic : RollingModel::none;
  return law;
}

struct Case {
  std::vector<Vec3> positions;  // ids 1, 2, ...
  Vec3 gravity;
  bool rolling;
};

Simulation make_case(const Case& c) {
  Particles p;
  for (std::size_t k = 0; k < c.positions.size(); ++k)
    p.add(std::int64_t(k + 1), c.positions[k], kRadius, kDensity, {kFloorSpeed, 0.0, 0.0});
  SimulationSettings s;
  s.domain.lower = {-0.02, -0.02, -0.01};
  s.domain.upper = {0.02, 0.02, 0.02};
  s.freeze_rotation = !c.rolling;
  Simulation sim(std::move(p), sticky_law(c.rolling), s);
  const std::size_t floor = sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, sticky_law(c.rolling)));
  sim.set_wall_velocity(floor, Vec3{kFloorSpeed, 0.0, 0.0});
  sim.set_gravity(c.gravity);
  return sim;
}

// Each particle's force, torque and rank (ids 1..n), from the rank that owns it (collective).
struct State {
  Vec3 force, torque;
  int owner = -1;
};
std::vector<State> owned_states(const Simulation& sim, std::size_t n) {
  std::vector<double> values(7 * n, 0.0);
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < sim.owned_count(); ++i) {
    double* v = values.data() + 7 * std::size_t(p.id[i] - 1);
    for (int a = 0; a < 3; ++a) {
      v[a] = p.force[i][a];
      v[3 + a] = p.torque[i][a];
    }
    v[6] = world_rank() + 1;
  }
  MPI_Allreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  std::vector<State> states(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double* v = values.data() + 7 * k;
    states[k] = {{v[0], v[1], v[2]}, {v[3], v[4], v[5]}, int(v[6]) - 1};
  }
  return states;
}

struct Outcome {
  double worst_difference = 0.0;  // |F - F_serial| / |F_serial| (and torques), over steps and particles
  double worst_jump = 0.0;        // at a step where a particle changed ranks: |F_x(now) - F_x(before)| / |F_x|
  double worst_torque_jump = 0.0; // the same for the torque's y component, over |F_x| R
  int crossings = 0;              // particle-steps at which the owner changed
  int straddling_steps = 0;       // steps at which the particles were owned by different ranks
};

Outcome run_across(const Case& c, int steps) {
  omp_set_num_threads(1);
  Simulation serial = make_case(c);
  Simulation decomposed = make_case(c);
  SlabSettings slabs;  // the first boundary at x = 0, the others 3 mm apart (a slab spans the range)
  for (int r = 1; r < world_size(); ++r) slabs.bounds.push_back(0.003 * (r - 1));
  slabs.rebalance_above = std::numeric_limits<double>::infinity();
  decompose_in_slabs(decomposed, MPI_COMM_WORLD, slabs);
  const std::size_t n = c.positions.size();
  std::vector<State> before(n);
  Outcome out;
  for (int s = 0; s < steps; ++s) {
    serial.step();
    decomposed.step();
    const Particles reference = sorted_by_id(serial.particles());
    const std::vector<State> states = owned_states(decomposed, n);
    std::vector<int> owners;
    for (std::size_t k = 0; k < n; ++k) {
      const State& now = states[k];
      owners.push_back(now.owner);
      const double f_scale = norm(reference.force[k]), t_scale = std::max(norm(reference.torque[k]), 1e-30);
      out.worst_difference = std::max(out.worst_difference, norm(now.force - reference.force[k]) / f_scale);
      if (c.rolling)
        out.worst_difference = std::max(out.worst_difference, norm(now.torque - reference.torque[k]) / t_scale);
      if (s > 0 && now.owner != before[k].owner) {
        ++out.crossings;
        out.worst_jump = std::max(out.worst_jump, std::abs(now.force.x - before[k].force.x) / std::abs(now.force.x));
        // The net torque of a sphere held still is ~0: its jump is measured against the friction
        // force's torque |F_x| R, which the rolling spring balances.
        out.worst_torque_jump = std::max(out.worst_torque_jump,
                                         std::abs(now.torque.y - before[k].torque.y) / (std::abs(now.force.x) * kRadius));
      }
      before[k] = now;
    }
    if (std::any_of(owners.begin(), owners.end(), [&](int o) { return o != owners.front(); })) ++out.straddling_steps;
  }
  return out;
}

// The lower block passes x = 0 after 12 ms, once the springs' transient has decayed (the stacked
// blocks' takes ~10 ms: at 6 ms the steady force still changes by 1e-2 per step). It changes rank
// at the first list rebuild after that: the floor carries the blocks as one, so the lists are
// rebuilt once per skin (0.4 mm) of travel, at 8 and 16 ms. Run to 20 ms.
int steps_to_cross() {
  const double m = sphere_mass(kRadius, kDensity);
  const double dt = 0.2 * std::sqrt(m / 1.0e4);
  return int(0.020 / dt);
}

}  // namespace

TEST(BoundaryCrossing, CarriedBlockKeepsItsTangentialSpring) {
  const Outcome o = run_across({{{kStart, 0.0, kRadius}}, {1.0, 0.0, -9.81}, false}, steps_to_cross());
  root_report("{} ranks, block: worst |F - F_1|/|F| = {:.1e} (tol 1e-9), jump at the crossing {:.1e} (tol 1e-6)",
              world_size(), o.worst_difference, o.worst_jump);
  EXPECT_LE(o.worst_difference, 1e-9);
  EXPECT_EQ(o.crossings, 1);
  EXPECT_LE(o.worst_jump, 1e-6);
}

TEST(BoundaryCrossing, StackedBlocksKeepTheirPairSpringWhileStraddling) {
  const double gap = 2.0 * kRadius - 1e-6;  // centre distance: the blocks touch
  const double dx = 0.2e-3, dz = std::sqrt(gap * gap - dx * dx);
  const Case c{{{kStart, 0.0, kRadius}, {kStart + dx, 0.0, kRadius + dz}}, {1.0, 0.0, -9.81}, false};
  const Outcome o = run_across(c, steps_to_cross());
  root_report("{} ranks, stacked blocks: worst |F - F_1|/|F| = {:.1e} (tol 1e-9), jump {:.1e} (tol 1e-6), {} steps "
              "straddling",
              world_size(), o.worst_difference, o.worst_jump, o.straddling_steps);
  EXPECT_LE(o.worst_difference, 1e-9);
  EXPECT_EQ(o.crossings, 2);
  EXPECT_LE(o.worst_jump, 1e-6);
  EXPECT_GT(o.straddling_steps, 400);  // 4 ms: ~600 steps
}

TEST(BoundaryCrossing, SphereKeepsItsRollingSpring) {
  const Outcome o = run_across({{{kStart, 0.0, kRadius}}, {0.5, 0.0, -9.81}, true}, steps_to_cross());
  root_report("{} ranks, sphere: worst |F - F_1|/|F|, |T - T_1|/|T| = {:.1e} (tol 1e-9), torque jump {:.1e} (tol 1e-6)",
              world_size(), o.worst_difference, o.worst_torque_jump);
  EXPECT_LE(o.worst_difference, 1e-9);
  EXPECT_EQ(o.crossings, 1);
  EXPECT_LE(o.worst_jump, 1e-6);
  EXPECT_LE(o.worst_torque_jump, 1e-6);
}
