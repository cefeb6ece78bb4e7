// Insertion during a run (the pour's way of adding particles): every rank draws the same sites
// from the same random stream and adds the particles whose sites it owns (Simulation::owns_site).
// Starting from no particle at all (the slabs split the domain's x equally), five batches of 12
// (or 11) spheres are thrown onto a floor between two end walls, 400 steps apart, and pile up. The particle set and the
// state equal the one-process run's: the same ids, positions to 1e-12 m (round-off from the order
// of additions grown over 2000 steps of impacts: measured 8e-15 m), forces to 1e-6 of the largest
// (an impact's force is stiff in the positions: measured 2e-9). A particle added
// on no rank or on two changes the count.
#include <gtest/gtest.h>
#include <omp.h>

#include "mpi_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

Simulation make_empty_box() {
  SimulationSettings s;
  s.domain.lower = {0.0, 0.0, -0.001};
  s.domain.upper = {0.03, 0.004, 0.03};
  s.skin = 0.4e-3;
  s.time_step = 4e-6;  // s, 0.2 of sqrt(m/k) for the smallest sphere
  Simulation sim(Particles{}, frictional_rolling_law(), s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictional_rolling_law()));
  sim.add_wall(Wall::plane("x0", {0, 0, 0}, {1, 0, 0}, frictional_rolling_law()));
  sim.add_wall(Wall::plane("x1", {0.03, 0, 0}, {-1, 0, 0}, frictional_rolling_law()));
  return sim;
}

// Batch b's particles (the same on every rank): a jittered row 3.5 + 1.6 b mm up (above the pile,
// ~1.6 mm a layer), every other batch
// shifted by half a spacing (they land in the pockets of the one below), thrown down at 1 m/s.
void rain(Simulation& sim, Rng& rng, int batch) {
  for (int i = 0; i < 12 - batch % 2; ++i) {
    const Vec3 x{0.0015 + (i + 0.5 * (batch % 2)) * 0.0023 + rng.uniform(-5e-5, 5e-5), 0.002, 0.0035 + 0.0016 * batch};
    const double r = rng.uniform(0.9e-3, 1.1e-3);
    const Vec3 v{rng.uniform(-0.05, 0.05), 0.0, -1.0};
    if (sim.owns_site(x)) sim.add_particle(batch * 100 + i + 1, x, r, 2500.0, v);
  }
}

}  // namespace

TEST(DecomposedInsertion, ParticlesAddedOnTheOwningRankMatchOneProcess) {
  omp_set_num_threads(1);
  Simulation serial = make_empty_box();
  Simulation decomposed = make_empty_box();
  decompose_in_slabs(decomposed, MPI_COMM_WORLD);
  Rng serial_rng(3), rng(3);
  std::size_t most_contacts = 0;  // in the one-process run, over the steps
  for (int batch = 0; batch < 5; ++batch) {
    rain(serial, serial_rng, batch);
    rain(decomposed, rng, batch);
    for (int s = 0; s < 400; ++s) {
      serial.step();
      decomposed.step();
      most_contacts = std::max(most_contacts, serial.contact_count());
    }
  }
  const Difference d = compare_with_serial(decomposed, serial);
  root_report("{} ranks: 58 particles inserted, up to {} contacts, |dx| = {:.1e} m (tol 1e-12), |dF|/F_max = {:.1e} "
              "(tol 1e-6)",
              world_size(), most_contacts, d.position, d.force);
  EXPECT_LE(d.position, 1e-12);
  EXPECT_LE(d.force, 1e-6);
  EXPECT_LE(d.torque, 1e-6);
  EXPECT_EQ(serial.particles().size(), 58u);
  EXPECT_GT(most_contacts, 5u);  // the spheres collide (measured 9 at once: they bounce and scatter)
  if (world_size() > 1) {
    EXPECT_LT(decomposed.owned_count(), 58u);  // the particles are spread over the ranks
  }
}
