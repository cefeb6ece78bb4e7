// The tiny preset through all four stages: the loads before and during lowering, and a run
// interrupted and resumed against one that ran straight through.
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dem/errors.hpp"
#include "experiment/strongbox.hpp"
#include "experiment/trapdoor_experiment.hpp"
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "io/snapshot.hpp"
#include "run_command.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

ExperimentConfig tiny_config(const std::vector<std::string>& overrides = {}) {
  Config c = Config::load_file((app::preset_directory() / "tiny.toml").string());
  c.apply_overrides(overrides);
  return ExperimentConfig::from(c);
}

// Records what the stage ends show.
struct LoadRecorder : ExperimentObserver {
  TrapdoorExperiment* experiment = nullptr;
  std::vector<Stage> finished;
  double walls_vertical_load = 0.0;   // N, sum over all walls at the end of spin-up
  double weight = 0.0;                // N, at the final gravity
  std::size_t snapshots = 0;

  void stage_finished(Stage stage, const std::string&) override {
    finished.push_back(stage);
    if (stage != Stage::spin_up) return;
    const Simulation& sim = experiment->simulation();
    walls_vertical_load = 0.0;
    for (const Wall& w : sim.walls()) walls_vertical_load -= w.force.z;
    weight = sim.particles().total_mass() * -sim.gravity().z;
  }
  void snapshot_due(const std::string&) override { ++snapshots; }
};

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("trapdem-test-" + name + "-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  return dir;
}

}  // namespace

TEST(TinyRun, AllStagesLoadsAndArching) {
  omp_set_num_threads(1);
  TrapdoorExperiment experiment(tiny_config());
  LoadRecorder recorder;
  recorder.experiment = &experiment;
  ASSERT_TRUE(experiment.run(recorder));
  ASSERT_EQ(recorder.finished,
            (std::vector<Stage>{Stage::pluviation, Stage::settling, Stage::spin_up, Stage::lowering}));
  EXPECT_EQ(recorder.snapshots, 2u + 4u);  // end of pluviation and settling; 0, 1, 2, 4 mm

  // At rest after spin-up the walls carry the weight at 50 g. The bed still creeps (kinetic
  // energy ~1e-7 of the potential), and the sum is of one step's loads: 0.5 % allows for that.
  EXPECT_NEAR(recorder.walls_vertical_load / recorder.weight, 1.0, 5e-3);

  const auto& rows = experiment.ground_reaction();
  ASSERT_GE(rows.size(), 40u);
  const GroundReactionRow& before = rows.front();
  // Before lowering the trapdoor carries the stress of the base beside it. The tiny box is four
  // particles deep and the trapdoor four diameters wide: a few force chains decide each wall's
  // load, and the side walls take part of the weight (Janssen), more near them than in the middle.
  // 25 % covers that; the paper-sized presets agree far closer.
  const double base_stress = 0.5 * (before.base_left.stress + before.base_right.stress);
  EXPECT_NEAR(before.trapdoor.stress / base_stress, 1.0, 0.25);
  EXPECT_GT(before.geostatic_stress, 0.0);
  // Arching: at 1-3 % of the trapdoor width the trapdoor carries well under half its initial stress.
  const double b = experiment.config().trapdoor.width;
  int in_range = 0;
  for (const GroundReactionRow& r : rows) {
    const double rel = r.trapdoor_displacement / b;
    if (rel < 0.01 || rel > 0.03) continue;
    ++in_range;
    EXPECT_LT(r.trapdoor.ratio, 0.5) << "at " << r.trapdoor_displacement * 1e3 << " mm";
  }
  EXPECT_GE(in_range, 2);
  // The load shed by the trapdoor goes to the base beside it.
  EXPECT_GT(rows.back().base_left.ratio + rows.back().base_right.ratio, 2.0);
}

// Interrupted (during lowering) and resumed, the run ends as one that ran straight through: the
// same thread count gives bitwise the same state and the same trapdoor.csv.
TEST(TinyRun, ResumedRunEndsIdentical) {
  const std::vector<std::string> small = {"pluviation.fill_height=0.02", "settling.max_time=0.04",
                                          "trapdoor.travel=0.0015", "output.snapshot_displacements=[0.0, 0.001]"};
  const fs::path config = fresh_dir("config") / "tiny-small.toml";
  fs::create_directories(config.parent_path());
  {
    Config c = Config::load_file((app::preset_directory() / "tiny.toml").string());
    c.apply_overrides(small);
    ExperimentConfig::from(c);
    std::ofstream(config) << c.resolved_toml();
  }
  app::RunOptions straight;
  straight.config_file = config.string();
  straight.out_dir = fresh_dir("straight").string();
  straight.quiet = true;
  straight.threads = 1;
  ASSERT_EQ(app::run_experiment(straight), 0);
  const Checkpoint end = read_checkpoint(fs::path(straight.out_dir) / "checkpoint.h5");

  for (std::int64_t stop : {end.stats.steps / 3, end.stats.steps - 700}) {
    app::RunOptions first = straight;
    first.out_dir = fresh_dir("interrupted").string();
    first.stop_at_step = stop;
    ASSERT_EQ(app::run_experiment(first), 130) << "the run should stop at step " << stop;
    app::RunOptions rest;
    rest.resume_dir = first.out_dir;
    rest.quiet = true;
    rest.threads = 1;
    ASSERT_EQ(app::run_experiment(rest), 0);
    const Checkpoint resumed = read_checkpoint(fs::path(first.out_dir) / "checkpoint.h5");
    ASSERT_EQ(resumed.stats.steps, end.stats.steps);
    ASSERT_EQ(resumed.particles.size(), end.particles.size());
    for (std::size_t i = 0; i < end.particles.size(); ++i) {
      ASSERT_EQ(resumed.particles.id[i], end.particles.id[i]);
      ASSERT_EQ(resumed.particles.position[i], end.particles.position[i]) << "particle " << i << ", stop " << stop;
    }
    EXPECT_EQ(read_text(fs::path(first.out_dir) / "trapdoor.csv"), read_text(fs::path(straight.out_dir) / "trapdoor.csv"));
    EXPECT_EQ(list_snapshots(fs::path(first.out_dir) / "snapshots.h5").size(),
              list_snapshots(fs::path(straight.out_dir) / "snapshots.h5").size());
    fs::remove_all(first.out_dir);
  }
  fs::remove_all(straight.out_dir);
  fs::remove_all(config.parent_path());
}

TEST(TinyRun, OutputFolderHoldingARunIsRefused) {
  const fs::path dir = fresh_dir("occupied");
  fs::create_directories(dir);
  std::ofstream(dir / "checkpoint.h5") << "x";
  app::RunOptions o;
  o.preset = "tiny";
  o.out_dir = dir.string();
  o.quiet = true;
  try {
    app::run_experiment(o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--resume"), std::string::npos) << e.what();
  }
  fs::remove_all(dir);
}

// A periodic depth (no front and back walls) runs through all stages too, and at the end of spin-up
// the base walls carry the weight on their own: without front and back walls nothing else can.
TEST(TinyRun, PeriodicDepthRunsAndTheBaseCarriesTheWeight) {
  omp_set_num_threads(1);
  TrapdoorExperiment experiment(tiny_config({"box.depth_boundary=periodic", "pluviation.fill_height=0.02",
                                             "settling.max_time=0.04", "trapdoor.travel=0.0015",
                                             "output.snapshot_displacements=[0.0]"}));
  for (const Wall& w : experiment.simulation().walls()) {
    EXPECT_NE(w.name, "front");
    EXPECT_NE(w.name, "back");
  }
  LoadRecorder recorder;
  recorder.experiment = &experiment;
  ASSERT_TRUE(experiment.run(recorder));
  EXPECT_EQ(recorder.finished.size(), 4u);
  // Same tolerance and reason as in AllStagesLoadsAndArching.
  EXPECT_NEAR(recorder.walls_vertical_load / recorder.weight, 1.0, 5e-3);
}
