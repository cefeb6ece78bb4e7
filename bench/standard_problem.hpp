#pragma once
// The standard benchmark's problem (the peers' one, /work/shared/peers/README.md), shared by
// bench/standard.cpp (one process) and bench/mpi_standard.cpp (ranks): a bed of 2 mm spheres in a
// width x 0.0182 x 0.2 m box under 50 g with the LIGGGHTS-equivalent contact law (hooke/stiffness,
// tangential history, rolling epsd2), walls at x = 0 and width, y = 0 and depth, z = 0.
#include <utility>

#include "dem/simulation.hpp"

namespace trapdem {

inline constexpr double kStandardDepth = 0.0182, kStandardHeight = 0.2;  // m

// skin: the Verlet skin (m); the standard problem's is 0.4 mm (bench/standard --skin varies it).
inline Simulation standard_problem(Particles particles, double width, double skin = 4.0e-4) {
  ContactLaw law;
  law.normal_stiffness = 1.0e6;
  law.tangential_stiffness = 5.0e5;
  law.restitution = 0.9;
  law.static_friction = 0.5;
  law.kinetic_friction = 0.5;
  law.rolling_friction = 0.2;
  law.rolling_model = RollingModel::elastic_plastic;
  law.rolling_stiffness = RollingStiffness::tangential;
  law.lever_arm = RollingLeverArm::effective_radius;
  law.rolling_damping = 0.0;  // LIGGGHTS epsd2: no rolling dashpot

  SimulationSettings s;
  s.time_step = 6.472e-7;
  s.skin = skin;
  s.domain.lower = {0.0, 0.0, 0.0};
  s.domain.upper = {width, kStandardDepth, kStandardHeight};

  Simulation sim(std::move(particles), law, s);
  sim.set_gravity(Vec3{0.0, 0.0, -50.0 * 9.81});
  sim.add_wall(Wall::plane("x0", {0, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("x1", {width, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("y0", {0, 0, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("y1", {0, kStandardDepth, 0}, {0, -1, 0}, law));
  sim.add_wall(Wall::plane("z0", {0, 0, 0}, {0, 0, 1}, law));
  return sim;
}

}  // namespace trapdem
