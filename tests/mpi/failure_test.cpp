// A failure on one rank stops every rank with that rank's message, none left waiting in an
// exchange (without the agreement the other ranks would wait forever and ctest's timeout fail
// the test). A row of 12 spheres, the last ones on the last rank: one leaves the domain (caught
// after the drift, before a rebuild would migrate it), or two collide too fast for their
// stiffness (caught at the end of the step).
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

#include "core/errors.hpp"
#include "mpi_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

// The message every rank stopped with, after the velocities given to some ids (1..12).
std::string failure_of(const std::vector<std::pair<int, Vec3>>& velocities, double stiffness, double time_step) {
  omp_set_num_threads(1);
  Particles p;
  for (int i = 0; i < 12; ++i) p.add(i + 1, {i * 0.004, 0.0, 0.0}, 1e-3, 2500.0);
  for (const auto& [id, v] : velocities) p.velocity[std::size_t(id - 1)] = v;
  ContactLaw law;
  law.normal_stiffness = stiffness;
  law.restitution = 0.5;
  SimulationSettings s;
  s.domain.lower = {-0.01, -0.01, -0.01};
  s.domain.upper = {0.05, 0.01, 0.01};
  s.time_step = time_step;
  Simulation sim(std::move(p), law, s);
  sim.set_gravity(Vec3{0, 0, 0});
  decompose_in_slabs(sim, MPI_COMM_WORLD);
  try {
    sim.run(100000);
  } catch (const SimulationError& e) {
    return e.what();
  }
  return "";
}

std::string last_rank() { return fmt::format("rank {} of {}", world_size() - 1, world_size()); }

}  // namespace

TEST(DecomposedFailure, AnEscapedParticleStopsEveryRankWithItsMessage) {
  const std::string message = failure_of({{12, {50.0, 0.0, 0.0}}}, 1.0e4, 0.0);  // m/s: id 12 flies out
  EXPECT_NE(message.find("particle left the domain"), std::string::npos) << message;
  EXPECT_NE(message.find("particle id 12 "), std::string::npos) << message;
  EXPECT_NE(message.find(last_rank()), std::string::npos) << message;
}

TEST(DecomposedFailure, AnOverlapBlowUpStopsEveryRankWithItsMessage) {
  // ids 11 and 12 run into each other at 40 m/s; 10 N/m is far too soft for that.
  const std::string message = failure_of({{11, {20.0, 0.0, 0.0}}, {12, {-20.0, 0.0, 0.0}}}, 10.0, 1e-6);
  EXPECT_NE(message.find("overlap blow-up"), std::string::npos) << message;
  EXPECT_NE(message.find("particle ids 11 and 12"), std::string::npos) << message;
  EXPECT_NE(message.find(last_rank()), std::string::npos) << message;
}
