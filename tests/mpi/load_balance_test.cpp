// Load balancing: slabs that start badly placed (every particle on rank 0) are moved at the first
// list rebuild to the x quantiles of the particles, so each rank holds N/R of them (to within the
// particles that share a quantile's x: none here, ids are on a jittered lattice); the run stays
// equal to one process (forces to 1e-12 of the largest after a step). Later, when a drift makes
// one rank hold more than 1 + rebalance_above times the mean, the next rebuild moves them again.
#include <gtest/gtest.h>
#include <omp.h>

#include "mpi_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

Simulation make_row(double drift) {
  Rng rng(5);
  Particles p;
  std::int64_t id = 1;
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 30; ++i)
        p.add(id++, {i * 0.002 + rng.uniform(-1e-4, 1e-4), j * 0.002 + rng.uniform(-1e-4, 1e-4), k * 0.002}, 1e-3,
              2500.0, {drift * i / 30.0 + rng.uniform(-0.01, 0.01), 0.0, 0.0});
  ContactLaw law;
  law.normal_stiffness = 1.0e4;
  law.tangential_stiffness = 0.5e4;
  law.restitution = 0.5;
  law.static_friction = law.kinetic_friction = 0.3;
  SimulationSettings s;
  s.domain = box(0.2);
  Simulation sim(std::move(p), law, s);
  sim.set_gravity(Vec3{0, 0, 0});
  return sim;
}

std::vector<std::int64_t> counts(const Simulation& sim) {
  std::int64_t mine = std::int64_t(sim.owned_count());
  std::vector<std::int64_t> all(static_cast<std::size_t>(world_size()));
  MPI_Allgather(&mine, 1, MPI_INT64_T, all.data(), 1, MPI_INT64_T, MPI_COMM_WORLD);
  return all;
}

}  // namespace

TEST(LoadBalance, BadlyPlacedSlabsAreMovedToTheQuantiles) {
  omp_set_num_threads(1);
  Simulation serial = make_row(0.0);
  Simulation sim = make_row(0.0);
  SlabSettings slabs;
  for (int r = 1; r < world_size(); ++r) slabs.bounds.push_back(1.0 + r);  // m: far beyond the particles
  slabs.rebalance_above = 0.1;
  SlabDecomposition& d = decompose_in_slabs(sim, MPI_COMM_WORLD, slabs);
  EXPECT_EQ(counts(sim).front(), 270);  // all on rank 0
  serial.step();
  sim.step();
  const std::vector<std::int64_t> n = counts(sim);
  const std::int64_t total = 270, mean = total / world_size();
  for (int r = 0; r < world_size(); ++r) EXPECT_NEAR(double(n[std::size_t(r)]), double(mean), 1.0) << "rank " << r;
  EXPECT_EQ(d.rebalances(), world_size() > 1 ? 1 : 0);
  const Difference diff = compare_with_serial(sim, serial);
  EXPECT_LE(diff.force, 1e-12);
  root_report("{} ranks: counts after the first rebuild {}, |dF|/F_max = {:.1e}", world_size(), fmt::join(n, " "),
              diff.force);
}

TEST(LoadBalance, ADriftTriggersAnotherRebalance) {
  omp_set_num_threads(1);
  // The particles' x velocity grows with x (0 to 0.6 m/s): the row stretches by ~20 % over the
  // run, the fixed boundaries fall behind the quantiles, the last slab fills up until a rebalance.
  Simulation sim = make_row(0.6);
  SlabSettings slabs;
  slabs.rebalance_above = 0.1;
  SlabDecomposition& d = decompose_in_slabs(sim, MPI_COMM_WORLD, slabs);  // balanced at the start
  std::int64_t worst = 0;
  for (int s = 0; s < 3000; ++s) {
    sim.step();
    const std::vector<std::int64_t> n = counts(sim);
    worst = std::max(worst, *std::max_element(n.begin(), n.end()));
  }
  root_report("{} ranks: {} rebalances, largest count seen {} (mean {})", world_size(), d.rebalances(), worst,
              270 / world_size());
  if (world_size() > 1) {
    EXPECT_GE(d.rebalances(), 1);
    // Between rebuilds a rank may exceed the limit by the particles that crossed since the last one.
    EXPECT_LE(double(worst), 1.25 * 270.0 / world_size());
  }
}
