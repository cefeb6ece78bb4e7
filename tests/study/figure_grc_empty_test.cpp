// Issue 41: `trapdem figure --grc` of a run whose trapdoor.csv has its header only (a run that has
// not reached its lowering) is refused naming the file, instead of an empty chart reported written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "experiment/ground_reaction.hpp"
#include "study/ground_reaction_overlay.hpp"
#include "../scratch_dir.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

TEST(FigureGrc, HeaderOnlyTrapdoorCsvIsRefused) {
  const test::ScratchDir dir("trapdem-grc-empty");
  fs::create_directories(dir / "run");
  std::ofstream(dir / "run" / "resolved.toml")
      << "name = \"empty\"\n[box]\nwidth = 0.2\ndepth = 0.01\nheight = 0.14\n"
         "[trapdoor]\nwidth = 0.02\ncentre = 0.1\ntravel = 0.01\ncavity_depth = 0.02\n"
         "[particles]\nsize = \"single\"\ndiameter = 0.002\n";
  std::ofstream(dir / "run" / "trapdoor.csv") << ground_reaction_csv({});
  try {
    write_ground_reaction_overlay(dir / "grc.png", {dir / "run"}, {});
    ADD_FAILURE() << "an empty curve was drawn";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no rows after the header"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(fs::exists(dir / "grc.png"));
}

}  // namespace
}  // namespace trapdem
