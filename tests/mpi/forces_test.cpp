// Per-particle forces and torques of a decomposed run against the same run in one process: a
// dense, polydisperse packing with friction and rolling resistance (so pairs carry histories),
// a floor, a side wall pushing into it and a finite plate, on R = 1..4 ranks (slabs along x).
//
// After the setup and one step the two runs differ only in the order the engine adds a
// particle's contact forces (the ghosts' shares come back after the sweep): round-off, ~1e-16 of
// the force scale per addition; the tolerance 1e-12 of the largest force leaves room for a few
// dozen additions. A force computed twice or lost at a boundary is of the order of a contact
// force, 1e-2 of the scale or more.
//
// Then 200 steps: the packing expands and drifts along x (its initial overlaps reach 14 % of a radius), particles
// cross slab boundaries and migrate with their contact histories, the lists are rebuilt many
// times. Round-off grows in a dense packing (each collision amplifies a difference), so the
// comparison after 200 steps allows 1e-8 of the scale; a lost history (a tangential or rolling
// spring restarted from zero) changes a contact force by a large fraction of itself.
#include <gtest/gtest.h>
#include <omp.h>

#include "../dem/test_support.hpp"
#include "mpi_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kDensity = 2500.0;
constexpr double kSpacing = 0.002;  // m; radii 0.95-1.07 mm: neighbours overlap
constexpr int kNx = 16, kNy = 5, kNz = 5;
constexpr double kDrift = 1.5;  // m/s along x, the packing's and the side wall's: particles cross slab boundaries

Simulation make_packing() {
  Particles p = jittered_lattice(7, kNx, kNy, kNz, kSpacing, kDensity, Vec3{kDrift, 0.0, 0.0});
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.05, 0.03, 0.03};
  s.max_overlap_fraction = 0.5;
  Simulation sim(std::move(p), frictional_rolling_law(), s);
  ContactLaw floor = frictional_rolling_law();
  floor.normal_stiffness = 4.0e4;
  floor.static_friction = floor.kinetic_friction = 0.6;
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, floor));
  ContactLaw side = frictional_rolling_law();
  side.rolling_model = RollingModel::constant_torque;
  side.lever_arm = RollingLeverArm::average_radius;
  const std::size_t pusher = sim.add_wall(Wall::plane("side", {0, 0, 0}, {1, 0, 0}, side));
  sim.set_wall_velocity(pusher, Vec3{kDrift + 0.02, 0.0, 0.0});
  ContactLaw plate = frictional_rolling_law();
  plate.rolling_friction = 0.0;
  plate.restitution = 0.8;
  // A plate against the packing's far side (y = max), spanning the middle of x: several slabs.
  sim.add_wall(Wall::rectangle("plate", {0.5 * kNx * kSpacing, (kNy - 0.5) * kSpacing + 0.85e-3, 0.005}, {1, 0, 0},
                               0.01, {0, 0, 1}, 0.003, plate));
  return sim;
}

void expect_walls_equal(const Simulation& decomposed, const Simulation& serial, double tolerance, bool all_touched) {
  for (std::size_t k = 0; k < serial.walls().size(); ++k) {
    const double scale = std::max(norm(serial.wall(k).force), 1e-30);
    EXPECT_LE(norm(decomposed.wall(k).force - serial.wall(k).force), tolerance * scale)
        << "load on wall " << serial.wall(k).name;
    if (all_touched) {
      EXPECT_GT(norm(serial.wall(k).force), 0.0) << "wall " << serial.wall(k).name << " is touched";
    }
  }
}

}  // namespace

// Each rank with 1 and with 3 OpenMP threads (the one-process run with 1): the sweep's thread
// blocks then include the ghosts, and partners in a later block get their shares after the sweep.
TEST(DecomposedForces, OneStepEqualsOneProcessToRoundOff) {
  for (const int threads : {1, 3}) {
    omp_set_num_threads(1);
    Simulation serial = make_packing();
    serial.step();
    omp_set_num_threads(threads);
    Simulation decomposed = make_packing();
    decompose_in_slabs(decomposed, MPI_COMM_WORLD);
    decomposed.step();
    omp_set_num_threads(1);
    const Difference d = compare_with_serial(decomposed, serial);
    root_report("{} ranks x {} threads, one step: |dF|/F_max = {:.1e}, |dT|/T_max = {:.1e} (tol 1e-12)", world_size(),
                threads, d.force, d.torque);
    EXPECT_LE(d.force, 1e-12) << threads << " threads";
    EXPECT_LE(d.torque, 1e-12) << threads << " threads";
    expect_walls_equal(decomposed, serial, 1e-12, true);
    // Every rank holds particles and ghosts (the split is real).
    if (world_size() > 1) {
      EXPECT_GT(decomposed.owned_count(), 0u);
      EXPECT_GT(decomposed.particles().size(), decomposed.owned_count());
    }
  }
}

TEST(DecomposedForces, ManyStepsWithMigrationEqualOneProcess) {
  omp_set_num_threads(1);
  Simulation serial = make_packing();
  Simulation decomposed = make_packing();
  SlabSettings fixed;  // the slabs stay where they are: particles must migrate
  fixed.rebalance_above = std::numeric_limits<double>::infinity();
  decompose_in_slabs(decomposed, MPI_COMM_WORLD, fixed);
  const std::size_t owned_at_start = [&] {
    decomposed.step();
    return decomposed.owned_count();
  }();
  serial.step();
  const std::vector<std::int64_t> ids_at_start(decomposed.particles().id.begin(),
                                               decomposed.particles().id.begin() + std::ptrdiff_t(owned_at_start));
  for (int s = 0; s < 200; ++s) {
    serial.step();
    decomposed.step();
  }
  const Difference d = compare_with_serial(decomposed, serial);
  root_report("{} ranks, 200 steps, {} rebuilds: |dF|/F_max = {:.1e}, |dT|/T_max = {:.1e}, |dx| = {:.1e} m (tol 1e-8)",
         world_size(), serial.stats().rebuilds, d.force, d.torque, d.position);
  EXPECT_LE(d.force, 1e-8);
  EXPECT_LE(d.torque, 1e-8);
  EXPECT_LE(d.velocity, 1e-8);
  expect_walls_equal(decomposed, serial, 1e-8, false);  // the side wall has lost touch by now
  EXPECT_EQ(decomposed.contact_count(), serial.contact_count());
  EXPECT_GE(serial.stats().rebuilds, 5);
  // Particles changed ranks: some owned at the start are owned elsewhere now (summed over ranks).
  if (world_size() > 1) {
    std::int64_t left = 0;
    const auto& ids = decomposed.particles().id;
    for (std::int64_t id : ids_at_start)
      left += std::find(ids.begin(), ids.begin() + std::ptrdiff_t(decomposed.owned_count()), id) ==
                      ids.begin() + std::ptrdiff_t(decomposed.owned_count())
                  ? 1
                  : 0;
    MPI_Allreduce(MPI_IN_PLACE, &left, 1, MPI_INT64_T, MPI_SUM, MPI_COMM_WORLD);
    root_report("{} particles migrated", left);
    EXPECT_GT(left, 0);
  }
}
