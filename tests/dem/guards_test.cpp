// The engine's guards: a run that cannot go on stops with a SimulationError whose message says
// what failed, where, and what to change.
#include <gtest/gtest.h>

#include <omp.h>

#include <string>

#include "core/errors.hpp"
#include "dem/simulation.hpp"
#include "dem/wall_list.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

// Runs until the engine throws (at most max_steps); returns the message, or "" if it never threw.
std::string error_of(Simulation& sim, int max_steps) {
  try {
    sim.run(max_steps);
  } catch (const SimulationError& e) {
    report("message: {}", e.what());
    return e.what();
  }
  return "";
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

// Three times the central-difference stability limit 2 sqrt(m/k): 27 spheres pressed together in
// a periodic box (overlaps ~2 %, jittered so that the forces do not cancel by symmetry) blow up
// within a few steps.
TEST(Guards, TimeStepFarTooLarge) {
  Particles p;
  Rng rng(9);
  std::int64_t id = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        p.add(id++,
              {0.00196 * (i + 0.5) + rng.uniform(-1e-5, 1e-5), 0.00196 * (j + 0.5) + rng.uniform(-1e-5, 1e-5),
               0.00196 * (k + 0.5) + rng.uniform(-1e-5, 1e-5)},
              0.001, 2500.0);
  SimulationSettings s;
  s.domain.lower = {0, 0, 0};
  s.domain.upper = {3 * 0.00196, 3 * 0.00196, 3 * 0.00196};
  s.domain.periodic[0] = s.domain.periodic[1] = s.domain.periodic[2] = true;
  s.skin = 0.0001;  // the box is only 3 diameters: the interaction range must fit twice
  s.time_step = 6.0 * std::sqrt(sphere_mass(0.001, 2500.0) / 1.0e4);
  Simulation sim(std::move(p), frictionless_law(1.0e4, 0.9), s);
  sim.set_gravity(Vec3{0, 0, 0});
  const std::string message = error_of(sim, 200);
  ASSERT_FALSE(message.empty()) << "a time step 6 sqrt(m/k) ran 200 steps without error";
  EXPECT_TRUE(contains(message, "time step")) << message;
  EXPECT_TRUE(contains(message, "critical step")) << message;  // the user sees dt against the limit
  // ...and is told to lower it, not to stiffen the contacts (which would make it worse).
  EXPECT_TRUE(contains(message, "exceeds the stability limit")) << message;
  EXPECT_FALSE(contains(message, "raise it")) << message;
}

TEST(Guards, ParticleFallingOutOfDomainIsNamed) {
  Particles p;
  p.add(5, {0.0, 0.0, 0.005}, 0.001, 2500.0);
  p.add(42, {0.005, 0.0, 0.001}, 0.001, 2500.0);  // no floor under anything
  SimulationSettings s;
  s.domain = box(0.01);
  s.domain.lower.z = 0.0;
  Simulation sim(std::move(p), frictionless_law(1.0e4, 0.5), s);
  const std::string message = error_of(sim, 100000);
  ASSERT_FALSE(message.empty()) << "a falling particle never left the domain";
  EXPECT_TRUE(contains(message, "left the domain")) << message;
  EXPECT_TRUE(contains(message, "particle id 42")) << message;  // the lower one leaves first
  EXPECT_FALSE(contains(message, "particle id 5 ")) << message;
  EXPECT_TRUE(contains(message, "wall")) << message;  // the likely cause: a missing wall
}

// Soft particle-particle contacts under high gravity: a column of three spheres on a stiff floor
// with k_n = 0.5 N/m between them (static overlap m g / k_n ~ r at 50 g).
TEST(Guards, OverlapBlowUpBetweenParticlesNamesStiffness) {
  Particles p;
  for (int k = 0; k < 3; ++k) p.add(10 + k, {0, 0, 0.001 + 0.002 * k}, 0.001, 2500.0);
  SimulationSettings s;
  s.domain = box(0.02);
  s.time_step = 1e-5;
  Simulation sim(std::move(p), frictionless_law(0.5, 0.5), s);
  sim.set_gravity(Vec3{0, 0, -500.0});
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictionless_law(1.0e4, 0.5)));
  const std::string message = error_of(sim, 100000);
  ASSERT_FALSE(message.empty()) << "no overlap guard";
  EXPECT_TRUE(contains(message, "overlap")) << message;
  EXPECT_TRUE(contains(message, "stiffness")) << message;
  EXPECT_TRUE(contains(message, "particle contact law (0.5 N/m)")) << message;  // the stiffness at fault
  EXPECT_TRUE(contains(message, "particle ids 10 and 11")) << message;  // the most loaded contact
}

// Soft floor, stiff particles: the floor contact is at fault, and the message must say so
// (the wall's name and its stiffness, not the particles').
TEST(Guards, OverlapBlowUpAtWallNamesWallAndItsStiffness) {
  Particles p;
  for (int k = 0; k < 3; ++k) p.add(20 + k, {0, 0, 0.001 + 0.002 * k}, 0.001, 2500.0);
  SimulationSettings s;
  s.domain = box(0.02);
  s.time_step = 1e-6;
  Simulation sim(std::move(p), frictionless_law(1.0e4, 0.5), s);
  sim.set_gravity(Vec3{0, 0, -500.0});
  sim.add_wall(Wall::plane("soft floor", {0, 0, 0}, {0, 0, 1}, frictionless_law(0.5, 0.5)));
  const std::string message = error_of(sim, 100000);
  ASSERT_FALSE(message.empty()) << "no overlap guard";
  EXPECT_TRUE(contains(message, "overlap")) << message;
  EXPECT_TRUE(contains(message, "soft floor")) << message;
  EXPECT_TRUE(contains(message, "particle id 20")) << message;
  EXPECT_TRUE(contains(message, "wall 'soft floor' contact law (0.5 N/m)")) << message;
  EXPECT_FALSE(contains(message, "1e+04 N/m")) << message;
}

// A particle within reach of more walls than a wall list holds (kMaxWallCandidates) is refused by
// name, whichever thread's block it falls in: the list is built by blocks of particles in parallel.
TEST(Guards, AParticleWithinReachOfTooManyWallsIsNamedOnAnyThreadCount) {
  Particles p;
  for (int i = 0; i < 40; ++i) p.add(100 + i, {0.01 * (i - 20), 0.0, 0.05}, 0.001, 2500.0);  // far from every wall
  p.add(7, {0.0, 0.0, 0.0011}, 0.001, 2500.0);  // just above the origin, where the walls meet
  std::vector<Wall> walls;
  const ContactLaw law = frictionless_law(1e5, 0.5);
  for (std::uint32_t k = 0; k <= kMaxWallCandidates; ++k) {
    const double tilt = 0.01 * k;  // planes through the origin, nearly horizontal: all within reach
    walls.push_back(Wall::plane("w" + std::to_string(k), {0, 0, 0}, {tilt, 0.0, 1.0}, law));
  }
  for (int threads : {1, 3}) {
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
    WallList list;
    try {
      build_wall_candidates(p, p.size(), walls, 0.0002, list);
      ADD_FAILURE() << "no error on " << threads << " threads";
    } catch (const InputError& e) {
      EXPECT_TRUE(contains(e.what(), "particle id 7 is within reach of 17 walls")) << e.what();
    }
    omp_set_num_threads(saved);
  }
  // Without the extra wall the list holds the particle's 16 and nobody else's.
  walls.pop_back();
  WallList list;
  build_wall_candidates(p, p.size(), walls, 0.0002, list);
  EXPECT_EQ(list.first.back(), kMaxWallCandidates);
}
