// The neighbour lists' rebuild criterion (Simulation::lists_outdated): between two builds the lists
// must hold every pair and every particle-wall contact that touches. Checked at every step against
// the brute-force O(N^2) touching test, for motions where the criterion's displacement box is
// small (a rain over a bed at rest, a cloud sliding along a wall) and where it is not (two clouds
// head on): exact, both sides use the same distance test. And the criterion's gain is counted: a
// cloud that moves as one rebuilds once per skin travelled, not once per half skin.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <utility>

#include "core/errors.hpp"
#include "dem/simulation.hpp"
#include "test_support.hpp"

using namespace trapdem;
using namespace trapdem::testing_support;

namespace {

constexpr double kRadius = 1.0e-3;  // m
constexpr double kSkin = 0.2e-3;    // m, the engine's default fraction of the diameter

// Steps `sim` `steps` times; after each, every touching pair must be a listed pair and every
// particle touching a wall one of that wall's candidates. Returns the touching pairs seen (summed
// over the steps), so that a test can tell it exercised contacts at all.
std::size_t step_checking_lists(Simulation& sim, int steps, const std::string& what) {
  std::size_t touching_seen = 0;
  for (int s = 0; s < steps; ++s) {
    sim.step();
    const Particles& p = sim.particles();
    const PairList list = sim.pairs();
    std::set<std::pair<std::uint32_t, std::uint32_t>> listed;
    for (std::uint32_t i = 0; i + 1 < list.first.size(); ++i)
      for (std::uint32_t k = list.first[i]; k < list.first[i + 1]; ++k)
        listed.emplace(std::min(i, list.partner[k]), std::max(i, list.partner[k]));
    for (const auto& pair : brute_force_pairs(p, sim.settings().domain, 0.0)) {
      ++touching_seen;
      if (listed.count(pair)) continue;
      ADD_FAILURE() << what << ", step " << s << ": particles " << pair.first << " and " << pair.second
                    << " touch but are not listed";
      return touching_seen;
    }
    const WallList& walls = sim.wall_candidates();
    for (std::uint32_t i = 0; i < p.size(); ++i) {
      for (std::uint32_t w = 0; w < sim.walls().size(); ++w) {
        if (wall_proximity(sim.walls()[w], p.position[i]).distance >= p.radius[i]) continue;
        const auto begin = walls.wall.begin() + walls.first[i], end = walls.wall.begin() + walls.first[i + 1];
        if (std::find(begin, end, w) != end) continue;
        ADD_FAILURE() << what << ", step " << s << ": particle " << i << " touches wall " << sim.walls()[w].name
                      << " but is not its candidate";
        return touching_seen;
      }
    }
  }
  return touching_seen;
}

SimulationSettings settings_in(double half_width) {
  SimulationSettings s;
  s.domain = box(half_width);
  s.skin = kSkin;
  s.time_step_fraction = 0.2;
  return s;
}

// Spheres of kRadius on a square lattice of `spacing` in x and y, `layers` high from `bottom`, all
// with velocity `v` (ids from `first_id`).
void add_layers(Particles& p, int per_side, int layers, double spacing, double bottom, const Vec3& v,
                std::int64_t first_id) {
  std::int64_t id = first_id;
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < per_side; ++j)
      for (int i = 0; i < per_side; ++i)
        p.add(id++, {(i - 0.5 * (per_side - 1)) * spacing, (j - 0.5 * (per_side - 1)) * spacing, bottom + k * spacing},
              kRadius, 2500.0, v);
}

// A rain at 1.5 m/s onto a bed at rest on a floor between two side walls, under 50 g.
Simulation rain_over_a_bed() {
  Particles p;
  add_layers(p, 6, 2, 2.0 * kRadius, kRadius, {}, 1);                        // the bed, at rest
  add_layers(p, 5, 3, 2.6 * kRadius, 8.0 * kRadius, {0.0, 0.0, -1.5}, 1000);  // the rain, falling
  Simulation sim(std::move(p), frictional_rolling_law(), settings_in(0.02));
  const ContactLaw wall_law = frictional_rolling_law();
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, wall_law));
  sim.add_wall(Wall::plane("left", {-6.0 * kRadius, 0, 0}, {1, 0, 0}, wall_law));
  sim.add_wall(Wall::plane("right", {6.0 * kRadius, 0, 0}, {-1, 0, 0}, wall_law));
  sim.set_gravity(Vec3{0.0, 0.0, -9.81 * 50.0});
  return sim;
}

}  // namespace

// The pour: a rain at 1.5 m/s (and gravity) onto a bed resting on the floor. The rain moves as
// one, so the lists are rebuilt about once per skin it falls; the beads land, bounce and push
// the bed into the side walls, and no contact is missed.
TEST(RebuildCriterion, ARainOverABedMissesNoContact) {
  Simulation sim = rain_over_a_bed();
  const std::size_t touching = step_checking_lists(sim, 3000, "rain over a bed");
  EXPECT_GT(touching, 3000u) << "the rain never reached the bed";
  EXPECT_GT(sim.stats().rebuilds, 5);
}

// Two clouds head on: their displacements' box is as wide as twice the largest displacement, and
// the criterion falls back on that: rebuilt every half skin of each cloud's travel, none missed.
TEST(RebuildCriterion, TwoCloudsHeadOnMissNoContact) {
  Particles p;
  add_layers(p, 4, 2, 2.5 * kRadius, -6.0 * kRadius, {0.0, 0.0, 1.0}, 1);
  add_layers(p, 4, 2, 2.5 * kRadius, 6.0 * kRadius, {0.0, 0.0, -1.0}, 100);
  Simulation sim(std::move(p), frictional_rolling_law(), settings_in(0.05));
  const std::size_t touching = step_checking_lists(sim, 2000, "two clouds head on");
  EXPECT_GT(touching, 1000u) << "the clouds never met";
}

// A cloud that slides along a wall at 1 m/s, as one, without touching itself: its displacements'
// box has no extent, so the pairs never need a rebuild; the wall does, once per skin travelled
// (a particle and a wall approach by the particle's whole displacement). Half the rebuilds of a
// criterion of half the skin per particle, and no wall contact missed.
TEST(RebuildCriterion, ACloudMovingAsOneRebuildsOncePerSkin) {
  Particles p;
  add_layers(p, 4, 3, 2.5 * kRadius, kRadius + 0.05e-3, {1.0, 0.0, 0.0}, 1);
  Simulation sim(std::move(p), frictional_rolling_law(), settings_in(0.5));
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictional_rolling_law()));
  const int steps = 4000;
  step_checking_lists(sim, steps, "a cloud moving as one");
  const double travelled = 1.0 * steps * sim.time_step();  // m
  const double per_skin = travelled / kSkin;
  ASSERT_GT(per_skin, 10.0) << "too short a run to count rebuilds";
  // The first build, then one each time the travel since the last passes the skin.
  EXPECT_LE(std::fabs(double(sim.stats().rebuilds) - (1.0 + std::floor(per_skin))), 1.0)
      << sim.stats().rebuilds << " rebuilds over " << per_skin << " skins travelled";
}

// The wall bound (DisplacementsSinceBuild::wall_bound) against its two parts: the particles' box
// from the door's travel D down to rest, as over a lowered trapdoor.
TEST(RebuildCriterion, TheWallBoundIsTheFarthestCornerWhenTheParticlesRideTheWall) {
  const Vec3 door{0.0, 0.0, -1.0e-3};  // m
  const DisplacementsSinceBuild riding{1.0e-6, {0.0, 0.0, -1.0e-3}, {0.0, 0.0, 0.0}};
  // The block on the door: the farthest corner (a particle at rest) is |D| from the door's
  // travel, where the sum of the two lengths is twice that.
  EXPECT_DOUBLE_EQ(riding.wall_bound(door), 1.0e-3);
  EXPECT_DOUBLE_EQ(riding.wall_bound({0.0, 0.0, 0.0}), 1.0e-3);  // a fixed wall: the largest length
  // A wall moving sideways while the particles sink: the corner (0, 0, -1 mm) against (1 mm, 0, 0)
  EXPECT_DOUBLE_EQ(riding.wall_bound({1.0e-3, 0.0, 0.0}), std::sqrt(2.0) * 1.0e-3);
  // Nothing tracked (no particle): the wall's own travel
  EXPECT_DOUBLE_EQ(DisplacementsSinceBuild{}.wall_bound({0.0, 3.0e-4, 4.0e-4}), 5.0e-4);
  // The largest length wins when the box is wide: particles moved 1 mm along each axis, both
  // ways, past a fixed wall (the farthest corner is sqrt(3) mm away)
  const DisplacementsSinceBuild spread{1.0e-6, {-1.0e-3, -1.0e-3, -1.0e-3}, {1.0e-3, 1.0e-3, 1.0e-3}};
  EXPECT_DOUBLE_EQ(spread.wall_bound({0.0, 0.0, 0.0}), 1.0e-3);
}

// The cloud sliding along a fixed floor, pushed (without touching) by a wall that moves with it:
// the floor needs a rebuild once per skin travelled, the pusher none; a criterion of the largest
// displacement plus the wall's travel would rebuild twice as often.
TEST(RebuildCriterion, AWallMovingWithTheCloudAddsNoRebuild) {
  Particles p;
  add_layers(p, 4, 3, 2.5 * kRadius, kRadius + 0.05e-3, {1.0, 0.0, 0.0}, 1);
  Simulation sim(std::move(p), frictional_rolling_law(), settings_in(0.5));
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictional_rolling_law()));
  Wall pusher = Wall::plane("pusher", {-5.0 * kRadius, 0, 0}, {1, 0, 0}, frictional_rolling_law());
  pusher.velocity = [](double) { return Vec3{1.0, 0.0, 0.0}; };
  sim.add_wall(std::move(pusher));
  const int steps = 4000;
  step_checking_lists(sim, steps, "a cloud and its pusher");
  const double per_skin = 1.0 * steps * sim.time_step() / kSkin;
  ASSERT_GT(per_skin, 10.0) << "too short a run to count rebuilds";
  EXPECT_LE(std::fabs(double(sim.stats().rebuilds) - (1.0 + std::floor(per_skin))), 1.0)
      << sim.stats().rebuilds << " rebuilds over " << per_skin << " skins travelled";
}

// A trapdoor lowered under a bed at 50 g: the block over the door follows it, the beds beside it
// rest on the fixed base, and the particles at the door's edges shear past both. No contact with
// a particle, the door or the base is missed at any step.
TEST(RebuildCriterion, ABedOverALoweredTrapdoorMissesNoContact) {
  Particles p;
  add_layers(p, 6, 3, 2.0 * kRadius, kRadius, {}, 1);
  Simulation sim(std::move(p), frictional_rolling_law(), settings_in(0.02));
  const ContactLaw law = frictional_rolling_law();
  const Vec3 x{1, 0, 0}, y{0, 1, 0};
  sim.add_wall(Wall::rectangle("base-left", {-4.0 * kRadius, 0, 0}, x, 2.0 * kRadius, y, 0.01, law));
  sim.add_wall(Wall::rectangle("base-right", {4.0 * kRadius, 0, 0}, x, 2.0 * kRadius, y, 0.01, law));
  Wall door = Wall::rectangle("door", {0, 0, 0}, x, 2.0 * kRadius, y, 0.01, law);
  door.velocity = [](double) { return Vec3{0.0, 0.0, -0.5}; };
  sim.add_wall(std::move(door));
  sim.add_wall(Wall::plane("left", {-6.0 * kRadius, 0, 0}, {1, 0, 0}, law));
  sim.add_wall(Wall::plane("right", {6.0 * kRadius, 0, 0}, {-1, 0, 0}, law));
  sim.add_wall(Wall::plane("front", {0, -6.0 * kRadius, 0}, {0, 1, 0}, law));
  sim.add_wall(Wall::plane("back", {0, 6.0 * kRadius, 0}, {0, -1, 0}, law));
  sim.set_gravity(Vec3{0.0, 0.0, -9.81 * 50.0});
  const std::size_t touching = step_checking_lists(sim, 3000, "a bed over a lowered trapdoor");
  EXPECT_GT(touching, 3000u) << "the bed's particles never touched";
  const double travelled = 0.5 * 3000 * sim.time_step();  // m, the door's
  EXPECT_GT(travelled, 5.0 * kSkin) << "the door moved too little to test the criterion";
  EXPECT_GT(sim.stats().rebuilds, 5);
}

// A skin changed between builds (an experiment's pour has a skin of its own): the lists stay
// those of the skin they were built with until they are outdated by that skin, so the change
// rebuilds nothing, and the next build uses the new skin. A bed at rest: no motion, no rebuild.
TEST(RebuildCriterion, ASkinChangeTakesEffectAtTheNextBuild) {
  Particles p;
  add_layers(p, 4, 2, 2.0 * kRadius, kRadius, {}, 1);
  Simulation sim(std::move(p), frictional_rolling_law(), settings_in(0.02));
  sim.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, frictional_rolling_law()));
  sim.step();
  ASSERT_EQ(sim.stats().rebuilds, 1);
  EXPECT_EQ(sim.list_state().skin_at_build, kSkin);
  sim.set_skin(3.0 * kSkin);
  EXPECT_EQ(sim.skin(), 3.0 * kSkin);
  sim.run(20);
  EXPECT_EQ(sim.stats().rebuilds, 1) << "a skin change alone rebuilt the lists";
  EXPECT_EQ(sim.list_state().skin_at_build, kSkin);
  sim.add_particle(1000, {0.0, 0.0, 0.01}, kRadius, 2500.0);  // new particles: the lists are rebuilt
  sim.step();
  EXPECT_EQ(sim.stats().rebuilds, 2);
  EXPECT_EQ(sim.list_state().skin_at_build, 3.0 * kSkin);
  EXPECT_THROW(sim.set_skin(0.0), InputError);
  EXPECT_THROW(sim.set_skin(-kSkin), InputError);
}

// The rain over the bed with a large skin while it falls, then the engine's skin while it lands
// and bounces (and the other way round): no contact missed at any step across either change, and
// the larger skin rebuilds less often over the same fall.
TEST(RebuildCriterion, ARainMissesNoContactAcrossSkinChanges) {
  Simulation large_first = rain_over_a_bed();
  large_first.set_skin(4.0 * kSkin);
  std::size_t touching = step_checking_lists(large_first, 800, "a rain, large skin");
  const std::int64_t large_rebuilds = large_first.stats().rebuilds;
  large_first.set_skin(kSkin);
  touching += step_checking_lists(large_first, 2200, "a rain, after the change to the small skin");
  EXPECT_GT(touching, 3000u) << "the rain never reached the bed";

  Simulation small_first = rain_over_a_bed();
  step_checking_lists(small_first, 800, "a rain, small skin");
  EXPECT_LT(2 * large_rebuilds, small_first.stats().rebuilds) << "a skin 4x as large rebuilt as often";
  small_first.set_skin(4.0 * kSkin);
  step_checking_lists(small_first, 2200, "a rain, after the change to the large skin");
}
