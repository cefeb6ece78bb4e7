// Issue 14, "run.log from the first line": the log is opened before anything else of the run is
// written, holds the error that stops a run, and a line that cannot be written (a full disk) stops
// the run at once with a FileError naming run.log (the run used to pour on with an empty log and
// fail only at the first snapshot).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "../io/io_test_support.hpp"
#include "core/errors.hpp"
#include "experiment/folder_run.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;
using io_testing::FileSizeLimit;
using io_testing::read_all;
using io_testing::ScratchDir;

const fs::path kTiny = fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml";

TEST(RunLog, TheFirstLineIsTheRunsDescriptionAndAnErrorIsLogged) {
  ScratchDir dir;
  FolderRunOptions o;
  o.config_file = kTiny;
  o.out_dir = dir / "run";
  o.quiet = true;
  o.threads = 1;
  o.stop_at_step = 1;
  EXPECT_FALSE(run_in_folder(o));
  const std::string log = read_all(dir / "run" / "run.log");
  EXPECT_EQ(log.rfind("trapdem run 'tiny': ", 0), 0u) << log;

  // A resume that fails is in the log too, after the line that says what was asked for.
  fs::remove(dir / "run" / "resolved.toml");
  FolderRunOptions r;
  r.resume_dir = dir / "run";
  r.quiet = true;
  EXPECT_THROW(run_in_folder(r), InputError);
  const std::string after = read_all(dir / "run" / "run.log");
  EXPECT_NE(after.find("trapdem run --resume " + (dir / "run").string()), std::string::npos) << after;
  EXPECT_NE(after.find("stopped by an error: cannot read the configuration file"), std::string::npos) << after;
}

// The constant torque's strength depends on the step (docs/element.md): run.log says so, with the
// step over the mean diameter, when its mu_r matters; not for elastic_plastic (the tiny preset's)
// nor for a mu_r of 0.001 (Calibrated's).
TEST(RunLog, AConstantTorqueRunNotesItsStepOverTheDiameter) {
  const std::string note = "note: constant_torque rolling resistance is weaker at a longer step";
  for (const auto& [overrides, expected] : std::vector<std::pair<std::vector<std::string>, bool>>{
           {{}, false},
           {{"contact.rolling_model=\"constant_torque\""}, true},
           {{"contact.rolling_model=\"constant_torque\"", "contact.rolling_friction=0.001"}, false}}) {
    ScratchDir dir;
    FolderRunOptions o;
    o.config_file = kTiny;
    o.out_dir = dir / "run";
    o.overrides = overrides;
    o.quiet = true;
    o.threads = 1;
    o.stop_at_step = 1;
    EXPECT_FALSE(run_in_folder(o));
    const std::string log = read_all(dir / "run" / "run.log");
    EXPECT_EQ(log.find(note) != std::string::npos, expected) << log;
    if (expected) {
      EXPECT_NE(log.find("step / mean diameter = "), std::string::npos) << log;
    }
  }
}

TEST(RunLog, AFullDiskStopsTheRunAtTheFirstLine) {
  ScratchDir dir;
  fs::create_directories(dir / "run");
  std::ofstream(dir / "run" / "run.log") << std::string(3990, '#') << '\n';  // 9 bytes below the limit
  FolderRunOptions o;
  o.config_file = kTiny;
  o.out_dir = dir / "run";
  o.quiet = true;
  o.threads = 1;
  try {
    const FileSizeLimit limit(4000);
    run_in_folder(o);
    ADD_FAILURE() << "the run went on with a log it cannot write";
  } catch (const FileError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("run.log"), std::string::npos) << m;
    EXPECT_NE(m.find("disk full"), std::string::npos) << m;
  }
  EXPECT_FALSE(fs::exists(dir / "run" / "snapshots.h5"));
  EXPECT_FALSE(fs::exists(dir / "run" / "checkpoint.h5"));
}

}  // namespace
}  // namespace trapdem
