// Issue 42: the trapdoor experiment in the centrifuge's rotating frame ([centrifuge]). A small tiny
// run flies from its spin-up on and, interrupted during the spin-up and during the lowering and
// resumed each time, ends bit for bit where the run straight through ends (the frame and its ramp
// are set again on a resume); the frame's configuration is refused where it cannot be a centrifuge's.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "experiment/experiment_config.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/presets.hpp"
#include "io/checkpoint.hpp"
#include "io/config.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;

namespace trapdem {
namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const std::vector<std::string> kSmallInFrame = {
    "pluviation.fill_height=0.02", "settling.max_time=0.04", "trapdoor.travel=0.0015",
    "output.snapshot_displacements=[0.0, 0.001]", "centrifuge.radius=3.0", "centrifuge.euler=false"};

ExperimentConfig tiny_with(const std::vector<std::string>& overrides) {
  Config c = Config::load_file((fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml").string());
  c.apply_overrides(overrides);
  return ExperimentConfig::from(c);
}

// The step at which run.log says `stage` finished.
std::int64_t stage_end_step(const std::string& log, const std::string& stage) {
  std::smatch m;
  EXPECT_TRUE(std::regex_search(log, m, std::regex("stage " + stage + " finished at t = [0-9.e+-]+ s \\(step ([0-9]+)\\)")))
      << log;
  return m.empty() ? 0 : std::stoll(m[1]);
}

TEST(CentrifugeRun, ResumedInTheFrameEndsIdentical) {
  const test::ScratchDir scratch("trapdem-centrifuge-run");
  const fs::path config = scratch / "tiny-in-frame.toml";
  {
    Config c = Config::load_file((fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml").string());
    c.apply_overrides(kSmallInFrame);
    ExperimentConfig::from(c);
    std::ofstream(config) << c.resolved_toml();
  }
  FolderRunOptions straight;
  straight.config_file = config;
  straight.out_dir = scratch / "straight";
  straight.quiet = true;
  straight.threads = 1;
  ASSERT_TRUE(run_in_folder(straight));
  const std::string log = read_text(straight.out_dir / "run.log");
  const std::int64_t settled = stage_end_step(log, "settling"), spun = stage_end_step(log, "spin-up");
  const Checkpoint end = read_checkpoint(straight.out_dir / "checkpoint.h5");
  ASSERT_LT(settled + 10, spun);
  ASSERT_LT(spun + 10, end.stats.steps);

  FolderRunOptions first = straight;
  first.out_dir = scratch / "interrupted";
  first.stop_at_step = settled + 20;  // within the spin-up's ramp (0.02 s, ~13 000 steps)
  ASSERT_FALSE(run_in_folder(first));
  for (const std::int64_t stop : {(spun + end.stats.steps) / 2, std::int64_t{0}}) {
    FolderRunOptions rest;
    rest.resume_dir = first.out_dir;
    rest.quiet = true;
    rest.threads = 1;
    rest.stop_at_step = stop;
    ASSERT_EQ(run_in_folder(rest), stop == 0) << "resumed to step " << stop;
  }
  const Checkpoint resumed = read_checkpoint(first.out_dir / "checkpoint.h5");
  ASSERT_EQ(resumed.stats.steps, end.stats.steps);
  EXPECT_EQ(read_text(first.out_dir / "trapdoor.csv"), read_text(straight.out_dir / "trapdoor.csv"));
  // resolved.toml records the frame and what it derives.
  const std::string resolved = read_text(straight.out_dir / "resolved.toml");
  EXPECT_NE(resolved.find("[centrifuge]"), std::string::npos) << resolved;
  EXPECT_NE(resolved.find("centrifuge_angular_velocity"), std::string::npos) << resolved;
}

// A run without [centrifuge] records none of its keys (its resume identity is what it was).
TEST(CentrifugeRun, NoFrameNoKeys) {
  Config c = Config::load_file((fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml").string());
  ExperimentConfig::from(c);
  EXPECT_EQ(c.resolved_toml().find("centrifuge"), std::string::npos);
}

struct BadFrame {
  std::vector<std::string> overrides;
  const char* key;
  const char* expected;
};

TEST(CentrifugeRun, ImpossibleFramesAreRefusedNamingTheKey) {
  const BadFrame cases[] = {
      {{"centrifuge.radius=0.01", "centrifuge.euler=false"}, "centrifuge.radius", "larger than the model's height"},
      {{"centrifuge.radius=0.05", "spin_up.g_level=500", "centrifuge.euler=false"}, "spin_up.g_level", "rad/s"},
      {{"centrifuge.radius=3.0", "centrifuge.width_orientation=\"diagonal\""}, "centrifuge.width_orientation",
       "expected one of"},
      {{"centrifuge.radius=3.0"}, "spin_up.ramp_time", "Euler acceleration"},
      {{"centrifuge.euler=false"}, "centrifuge.radius", "missing"},
  };
  for (const BadFrame& bad : cases) {
    try {
      tiny_with(bad.overrides);
      ADD_FAILURE() << bad.key << " was accepted";
    } catch (const InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(bad.key), std::string::npos) << m;
      EXPECT_NE(m.find(bad.expected), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace trapdem
