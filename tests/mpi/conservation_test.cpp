// Momentum on 3 ranks: a packing with no wall and no gravity, its initial overlaps (up to 14 % of
// a radius) driving it apart, friction and rolling resistance on. Every contact force acts on
// both bodies with opposite signs, whichever rank computes it, so the total momentum stays what
// it was. Round-off: each step adds ~1e-16 of the contact impulses (~1e-5 kg m/s per particle per
// step here) per addition, ~1e-19 kg m/s over the run; the tolerance is 1e-12 of sum m |v|. A
// share lost at a boundary (a ghost's force not returned to its owner) removes a contact
// impulse, ~1e-2 of sum m |v| or more.
#include <gtest/gtest.h>
#include <omp.h>

#include "mpi_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

TEST(DecomposedConservation, MomentumOfAFreePackingIsConserved) {
  omp_set_num_threads(1);
  Rng rng(11);
  Particles p;
  std::int64_t id = 1;
  const double spacing = 0.002;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j)
      for (int i = 0; i < 18; ++i) {
        const Vec3 x{i * spacing + rng.uniform(-5e-5, 5e-5), j * spacing + rng.uniform(-5e-5, 5e-5),
                     k * spacing + rng.uniform(-5e-5, 5e-5)};
        p.add(id++, x, rng.uniform(0.95e-3, 1.07e-3), 2500.0,
              {rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)},
              {rng.uniform(-50, 50), rng.uniform(-50, 50), rng.uniform(-50, 50)});
      }
  SimulationSettings s;
  s.domain = box(0.1);
  s.max_overlap_fraction = 0.5;
  Simulation sim(std::move(p), frictional_rolling_law(), s);
  sim.set_gravity(Vec3{0, 0, 0});
  SlabSettings fixed;  // particles cross the slabs' boundaries as the packing expands
  fixed.rebalance_above = std::numeric_limits<double>::infinity();
  decompose_in_slabs(sim, MPI_COMM_WORLD, fixed);

  auto momentum = [&](double& scale) {
    const Particles all = gather_particles(sim, MPI_COMM_WORLD);  // in id order: the same sums on every rank
    Vec3 total{};
    scale = 0.0;
    for (std::size_t i = 0; i < all.size(); ++i) {
      total += all.mass[i] * all.velocity[i];
      scale += all.mass[i] * norm(all.velocity[i]);
    }
    return total;
  };
  double scale_before = 0.0, scale_after = 0.0;
  sim.step();
  EXPECT_GT(sim.contact_count(), 100u);  // the packing is in contact at the start
  const Vec3 before = momentum(scale_before);
  sim.run(400);
  const Vec3 after = momentum(scale_after);
  const double drift = norm(after - before) / scale_before;
  root_report("{} ranks: |P_end - P_start| / sum m|v| = {:.1e} (tol 1e-12); sum m|v| {:.3e} -> {:.3e} kg m/s, {} rebuilds",
              world_size(), drift, scale_before, scale_after, sim.stats().rebuilds);
  EXPECT_LE(drift, 1e-12);
  EXPECT_GE(sim.stats().rebuilds, 5);
}
