#include <gtest/gtest.h>

#include "dem/simulation.hpp"

using namespace trapdem;

TEST(Smoke, SphereFallsOnFloor) {
  Particles p;
  p.add(1, {0, 0, 0.01}, 0.001, 2500.0);
  SimulationSettings s;
  s.domain.lower = {-0.1, -0.1, -0.01};
  s.domain.upper = {0.1, 0.1, 0.1};
  ContactLaw law;
  law.restitution = 0.3;
  Simulation sim(std::move(p), law, s);
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  sim.run(200000);
  EXPECT_NEAR(sim.particles().position[0].z, 0.001, 1e-4);
}
