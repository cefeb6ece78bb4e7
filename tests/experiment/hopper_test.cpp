// The hopper's box-full rule: a pour whose deposit has reached the band's ceiling, with no free
// site left there, ends (fewer particles than the count) instead of pushing particles into the
// heap; a deposit below the ceiling, or at it with the band's sites free, goes on pouring.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <map>
#include <memory>
#include <string>

#include "../io/io_test_support.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/pluviation.hpp"
#include "experiment/strongbox.hpp"
#include "io/config.hpp"

using namespace trapdem;

namespace {

// The tiny preset (80 x 14 x 60 mm box, beads of 3.6-4.4 mm) poured by count, with no flow rate:
// every free site of the band takes a particle at each insertion.
ExperimentConfig counted_pour() {
  Config c = Config::load_file(std::string(TRAPDEM_SOURCE_DIR) + "/presets/tiny.toml");
  c.apply_overrides({"pluviation.fill_height=0.0", "pluviation.count=700"});
  return ExperimentConfig::from(c);
}

// The strongbox without gravity, holding a lattice of beads of the largest diameter at rest, 4.5
// mm apart (no two touch), in layers from `highest_centre` (m) down to 2 d_max below the rim. A
// lattice 4.5 mm apart leaves no point among its layers farther than 3.9 mm (half the cube's
// diagonal) from a bead's centre, inside the 4.62 mm at which a site counts as blocked.
std::unique_ptr<Simulation> box_with_lattice(const ExperimentConfig& c, double highest_centre) {
  SimulationSettings s;
  s.time_step = c.time_step();
  s.skin = c.skin();
  s.domain = strongbox_domain(c);
  auto sim = std::make_unique<Simulation>(Particles{}, c.material.particle, s);
  sim->set_gravity(Vec3{0.0, 0.0, 0.0});  // a Simulation starts at 1 g: the lattice would fall away
  for (Wall& w : strongbox_walls_for(c)) sim->add_wall(std::move(w));
  const double d = c.material.sizes.max_diameter(), spacing = 4.5e-3;
  std::int64_t id = 1000000;  // beyond the hopper's ids
  for (double z = highest_centre; z >= c.box.height - 2.0 * d; z -= spacing)
    for (double x = 0.5 * spacing; x + 0.5 * d < c.box.width; x += spacing)
      for (double y = 0.5 * spacing; y + 0.5 * d < c.box.depth; y += spacing)
        sim->add_particle(id++, {x, y, z}, 0.5 * d, c.material.density);
  return sim;
}

// Pours until the hopper is finished or `insertions` insertion intervals have passed.
void pour_for(Hopper& hopper, Simulation& sim, int insertions, double interval) {
  const double end = sim.time() + insertions * interval;
  while (sim.time() < end && !hopper.finished(sim)) {
    hopper.pour(sim);
    sim.step();
  }
}

// The time between insertions: a layer falls one site spacing (1.1 d_max) at the entry speed.
double insertion_interval(const ExperimentConfig& c, const Hopper& h) {
  const double g = ExperimentConfig::standard_gravity, v = h.entry_speed(), s = 1.1 * c.material.sizes.max_diameter();
  return (-v + std::sqrt(v * v + 2.0 * g * s)) / g;
}

}  // namespace

TEST(Hopper, ABoxFullToTheBandsCeilingEndsThePourShortOfItsCount) {
  omp_set_num_threads(1);
  const ExperimentConfig c = counted_pour();
  Hopper hopper(c);
  const double d = c.material.sizes.max_diameter();
  // The lattice reaches past the ceiling: the band cannot rise above it, and every site is blocked.
  auto sim = box_with_lattice(c, hopper.band_ceiling() + d);
  pour_for(hopper, *sim, 40, insertion_interval(c, hopper));
  EXPECT_TRUE(hopper.box_full());
  EXPECT_TRUE(hopper.finished(*sim));
  EXPECT_EQ(hopper.inserted(), 0);  // no site was free: nothing was pushed into the heap
  EXPECT_NEAR(hopper.band_ceiling(), c.box.height + 3.0 * d, 1e-15);  // m: the rule's reference height

  // The state survives a checkpoint; a checkpoint written before the rule restores as not full.
  std::map<std::string, std::string> state = hopper.state();
  Hopper restored(c);
  restored.restore(state);
  EXPECT_TRUE(restored.box_full());
  state.erase("hopper.box_full");
  state.erase("hopper.stalled_insertions");
  Hopper older(c);
  older.restore(state);
  EXPECT_FALSE(older.box_full());
}

TEST(Hopper, ADepositAtTheCeilingWithTheBandsSitesFreeGoesOnPouring) {
  omp_set_num_threads(1);
  const ExperimentConfig c = counted_pour();
  Hopper hopper(c);
  const double d = c.material.sizes.max_diameter();
  // The top 1.7 d_max above the rim: the band sits at its ceiling (it would ride at top + 2 d), but
  // the lattice's highest beads (1.8 d_max below it) are beyond the blocking reach. Three
  // insertions: the layers they place fill that gap, and a pour that went on would be full.
  auto sim = box_with_lattice(c, c.box.height + 1.2 * d);
  pour_for(hopper, *sim, 3, insertion_interval(c, hopper));
  EXPECT_FALSE(hopper.box_full());
  EXPECT_GT(hopper.inserted(), 0);
}

TEST(Hopper, ADepositBelowTheRimGoesOnPouring) {
  omp_set_num_threads(1);
  const ExperimentConfig c = counted_pour();
  Hopper hopper(c);
  auto sim = box_with_lattice(c, c.box.height - c.material.sizes.max_diameter());
  pour_for(hopper, *sim, 3, insertion_interval(c, hopper));
  EXPECT_FALSE(hopper.box_full());
  EXPECT_GT(hopper.inserted(), 0);
}

// A pour by fill height in a box too low for it ends at the band's ceiling, and run.log says so
// without naming a count that was never asked for (it named "of the 0 particles asked for").
TEST(Hopper, ABoxFullBeforeTheFillHeightIsSaidSo) {
  omp_set_num_threads(1);
  const io_testing::ScratchDir scratch("trapdem-hopper-full");
  FolderRunOptions o;
  o.config_file = std::string(TRAPDEM_SOURCE_DIR) + "/presets/tiny.toml";
  // At a nominal solid fraction of 0.75 the poured mass reaches 30 mm long after the real deposit (a
  // solid fraction below 0.6) has filled the box.
  o.overrides = {"box.height=0.03", "pluviation.fill_height=0.03", "pluviation.packing_fraction=0.75", "settling.max_time=0.01",
                 "spin_up.ramp_time=0.005", "trapdoor.travel=0.0005", "output.snapshot_displacements=[0.0]"};
  o.out_dir = scratch / "run";
  o.quiet = true;
  o.threads = 1;
  ASSERT_TRUE(run_in_folder(o));
  const std::string log = io_testing::read_all(scratch / "run" / "run.log");
  EXPECT_NE(log.find("particles poured, before the nominal surface reached the fill height (30.0 mm), and the pour "
                     "ends there"),
            std::string::npos)
      << log;
  EXPECT_EQ(log.find("of the 0 particles"), std::string::npos) << log;
}
