// A failure on one rank stops every rank with that rank's message, none left waiting in an
// exchange (without the agreement the other ranks would wait forever and ctest's timeout fail
// the test). Here a particle owned by the last rank leaves the domain.
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

#include "core/errors.hpp"
#include "mpi_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

TEST(DecomposedFailure, AnEscapedParticleStopsEveryRankWithItsMessage) {
  omp_set_num_threads(1);
  Particles p;
  for (int i = 0; i < 12; ++i) p.add(i + 1, {i * 0.004, 0.0, 0.0}, 1e-3, 2500.0);
  p.velocity.back() = {50.0, 0.0, 0.0};  // m/s: the last particle (on the last rank) flies out
  ContactLaw law;
  law.normal_stiffness = 1.0e4;
  law.restitution = 0.5;
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.05, 0.01, 0.01};
  Simulation sim(std::move(p), law, s);
  sim.set_gravity(Vec3{0, 0, 0});
  decompose_in_slabs(sim, MPI_COMM_WORLD);
  std::string message;
  try {
    sim.run(100000);
  } catch (const SimulationError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("particle left the domain"), std::string::npos) << message;
  EXPECT_NE(message.find("particle id 12 "), std::string::npos) << message;
  EXPECT_NE(message.find(fmt::format("rank {} of {}", world_size() - 1, world_size())), std::string::npos) << message;
}

// The same at the end of a step: two particles on the last rank collide too fast for their
// stiffness (an overlap beyond the guard's 25 % of a radius).
TEST(DecomposedFailure, AnOverlapBlowUpStopsEveryRankWithItsMessage) {
  omp_set_num_threads(1);
  Particles p;
  for (int i = 0; i < 12; ++i) p.add(i + 1, {i * 0.004, 0.0, 0.0}, 1e-3, 2500.0);
  p.velocity[10] = {20.0, 0.0, 0.0};  // m/s: ids 11 and 12 run into each other
  p.velocity[11] = {-20.0, 0.0, 0.0};
  ContactLaw law;
  law.normal_stiffness = 10.0;  // N/m: far too soft for 40 m/s
  law.restitution = 0.5;
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.05, 0.01, 0.01};
  s.time_step = 1e-6;
  Simulation sim(std::move(p), law, s);
  sim.set_gravity(Vec3{0, 0, 0});
  decompose_in_slabs(sim, MPI_COMM_WORLD);
  std::string message;
  try {
    sim.run(100000);
  } catch (const SimulationError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("overlap blow-up"), std::string::npos) << message;
  EXPECT_NE(message.find("particle ids 11 and 12"), std::string::npos) << message;
  EXPECT_NE(message.find(fmt::format("rank {} of {}", world_size() - 1, world_size())), std::string::npos) << message;
}
