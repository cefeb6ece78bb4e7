// Walls made of several rectangles: a seam between coplanar rectangles must not add a contact,
// while a convex edge that a particle really touches must.
#include <gtest/gtest.h>

#include "dem/simulation.hpp"

using namespace trapdem;

namespace {

// A sphere resting on two coplanar rectangles that meet at x = 0 (as the trapdoor meets the base),
// and a vertical rectangle below the seam (the cavity wall), whose top edge lies on the seam too.
Simulation sphere_on_seam(double x_offset) {
  Particles p;
  const double r = 0.001;
  p.add(1, {x_offset, 0.0, r}, r, 2500.0);
  SimulationSettings s;
  s.domain.lower = {-0.02, -0.02, -0.02};
  s.domain.upper = {0.02, 0.02, 0.02};
  s.time_step_fraction = 0.1;
  ContactLaw law;
  law.restitution = 0.2;
  Simulation sim(std::move(p), law, s);
  sim.add_wall(Wall::rectangle("base", {-0.005, 0, 0}, {1, 0, 0}, 0.005, {0, 1, 0}, 0.005, law));
  sim.add_wall(Wall::rectangle("trapdoor", {0.005, 0, 0}, {1, 0, 0}, 0.005, {0, 1, 0}, 0.005, law));
  sim.add_wall(Wall::rectangle("cavity", {0, 0, -0.005}, {0, 0, 1}, 0.005, {0, 1, 0}, 0.005, law));
  sim.set_gravity(Vec3{0, 0, -9.81});
  return sim;
}

}  // namespace

// At rest the walls together carry exactly the weight, wherever the sphere sits relative to the
// seam: a double-counted seam contact would lift the sphere higher (less overlap) but the total
// would still balance, so the test checks the overlap too: it must equal m g / k_n, the single
// contact's static overlap, within 1e-6 relative (the bed is at rest to round-off after damping).
TEST(WallSeam, SphereNearSeamFeelsOneContact) {
  for (double offset : {-2e-4, -1e-5, 0.0, 1e-5, 2e-4}) {
    Simulation sim = sphere_on_seam(offset);
    sim.run(40000);
    const double m = sim.particles().mass[0];
    const double expected_overlap = m * 9.81 / sim.particle_law().normal_stiffness;
    const double overlap = sim.particles().radius[0] - sim.particles().position[0].z;
    EXPECT_NEAR(overlap, expected_overlap, 1e-6 * expected_overlap) << "offset " << offset;
    Vec3 total;
    for (const Wall& w : sim.walls()) total += w.force;
    EXPECT_NEAR(-total.z, m * 9.81, 1e-9 * m * 9.81) << "offset " << offset;
  }
}

// When the trapdoor has dropped, the base's edge is convex: a sphere centred over the gap and
// touching only that edge must be pushed away from it along the edge normal.
TEST(WallSeam, ConvexEdgeStillActs) {
  Simulation sim = sphere_on_seam(0.0);
  Vec3 lowered = sim.wall(1).origin;
  lowered.z -= 0.004;  // trapdoor lowered 4 mm
  sim.restore_wall_state(1, lowered, {0, 0, -0.004}, {}, {}, {});
  auto& p = sim.particles_mutable();
  p.position[0] = {0.0007, 0.0, 0.0007};  // 0.99 mm from the edge at (0, 0): overlap 0.01 mm
  sim.set_gravity(Vec3{0, 0, 0});
  sim.step();
  const Vec3 f = sim.particles().force[0];
  EXPECT_GT(f.x, 0.0);
  EXPECT_GT(f.z, 0.0);
  EXPECT_NEAR(f.x, f.z, 1e-9 * norm(f));  // along the 45 degree edge normal
}
