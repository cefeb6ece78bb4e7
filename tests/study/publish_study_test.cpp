// scripts/publish-study.sh: what a reader of a study needs, without its HDF5 files. A study carried
// from machine to machine (one case a session, each in a new folder, the published cases copied
// back) publishes into the same folder each time: the finished runs are copied, an unfinished one
// is left out with --finished-only, the particle data stays behind, and study.log keeps every
// session's lines once each.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/text_file.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

const fs::path kScript = fs::path(TRAPDEM_SOURCE_DIR) / "scripts" / "publish-study.sh";

void write(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

// A run folder: finished or not, with a checkpoint and particle-level fields that must not be
// published and the gridded field history that must.
void make_run(const fs::path& run, bool complete) {
  write(run / "resolved.toml", "name = \"" + run.filename().string() + "\"\n");
  write(run / "run.json", complete ? "{\"complete\": true}\n" : "{\"complete\": false}\n");
  write(run / "run.log", "log\n");
  write(run / "checkpoint.h5", "particle data");
  write(run / "analysis" / "metrics.json", "{}\n");
  write(run / "analysis" / "shear_strain.png", "png");
  write(run / "analysis" / "fields.h5", "particle-level fields");
  write(run / "analysis" / "field_history.h5", "gridded fields");
}

int publish(const fs::path& study, const fs::path& dest) {
  const std::string command = "bash '" + kScript.string() + "' '" + study.string() + "' '" + dest.string() +
                              "' --finished-only --figures > /dev/null";
  return std::system(command.c_str());
}

}  // namespace

TEST(PublishStudy, TwoSessionsPublishTheirCasesAndTheWholeLog) {
  const test::ScratchDir dir("trapdem-publish");
  const fs::path dest = dir / "published";

  // First session: case a finished, b running.
  const fs::path first = dir / "first";
  make_run(first / "cases" / "a", true);
  make_run(first / "cases" / "b", false);
  write(first / "study.json", "{}\n");
  write(first / "study.log", "10:00  [1/2] a: running\n11:00  [1/2] a: finished\n11:00  [2/2] b: running\n");
  ASSERT_EQ(publish(first, dest), 0);
  EXPECT_TRUE(fs::exists(dest / "cases" / "a" / "run.json"));
  EXPECT_TRUE(fs::exists(dest / "cases" / "a" / "analysis" / "metrics.json"));
  EXPECT_TRUE(fs::exists(dest / "cases" / "a" / "analysis" / "shear_strain.png"));
  EXPECT_TRUE(fs::exists(dest / "cases" / "a" / "analysis" / "field_history.h5"));
  EXPECT_FALSE(fs::exists(dest / "cases" / "a" / "checkpoint.h5"));
  EXPECT_FALSE(fs::exists(dest / "cases" / "a" / "analysis" / "fields.h5"));
  EXPECT_FALSE(fs::exists(dest / "cases" / "b"));

  // Second session, a new folder: a copied back, b run afresh to the end. Its log begins anew.
  const fs::path second = dir / "second";
  make_run(second / "cases" / "a", true);
  make_run(second / "cases" / "b", true);
  write(second / "study.log", "20:00  [1/2] a: finished before, skipped\n20:00  [2/2] b: running\n21:00  [2/2] b: finished\n");
  ASSERT_EQ(publish(second, dest), 0);
  EXPECT_TRUE(fs::exists(dest / "cases" / "b" / "run.json"));
  EXPECT_EQ(read_text_file(dest / "study.log"),
            "10:00  [1/2] a: running\n11:00  [1/2] a: finished\n11:00  [2/2] b: running\n"
            "20:00  [1/2] a: finished before, skipped\n20:00  [2/2] b: running\n21:00  [2/2] b: finished\n");

  // A folder that began from the published log (docs/study.md's way) adds no line twice.
  const std::string published = read_text_file(dest / "study.log");
  write(second / "study.log", published + "22:00  report written\n");
  ASSERT_EQ(publish(second, dest), 0);
  EXPECT_EQ(read_text_file(dest / "study.log"), published + "22:00  report written\n");
}
