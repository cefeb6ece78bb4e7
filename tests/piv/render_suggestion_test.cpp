// `trapdem render DIR` suggests PIV from the start of lowering (apps/piv_command.hpp): on a run
// whose first snapshots are taken before the trapdoor moves (pour, settling, spin-up: 0 mm), the
// command in camera/scale.txt lists the images from the last of them on, not the pour's.
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <string>

#include "io/text_file.hpp"
#include "piv/dem_camera.hpp"
#include "piv_command.hpp"
#include "../scratch_dir.hpp"
#include "../study/synthetic_run.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

TEST(LoweringStart, TheLastSnapshotBeforeTheTrapdoorMoves) {
  EXPECT_EQ(lowering_start({0.0, 0.0, 0.0, 0.001, 0.002}), 2u);
  EXPECT_EQ(lowering_start({0.0, 0.001}), 0u);
  EXPECT_EQ(lowering_start({0.0, 0.0}), 1u);
  EXPECT_EQ(lowering_start({}), 0u);
}

TEST(RenderSuggestion, PivStartsAtTheFirstLoweringImage) {
  const test::ScratchDir scratch("trapdem-render-suggestion");
  const fs::path dir = scratch / "run";
  // Snapshots 000 (pour), 001 (settled), 002 (start of lowering) at 0 mm, then 1 and 2 mm.
  test::make_synthetic_run(dir, {0.0, 0.0, 0.0, 0.001, 0.002},
                           [](Point2 p, double delta) { return Point2{0.0, -delta * p.z / 0.12}; });
  app::RenderOptions o;
  o.dir = dir.string();
  o.px_per_mm = 1.0;
  ASSERT_EQ(app::run_render_command(o), 0);
  const std::string scale = read_text_file(dir / "camera" / "scale.txt");
  std::smatch m;
  ASSERT_TRUE(std::regex_search(scale, m, std::regex("# trapdem piv ([^\n]*)"))) << scale;
  const std::string command = m[1];
  const std::string camera = (dir / "camera").string();
  EXPECT_EQ(command.rfind(camera + "/002_0mm.png " + camera + "/003_1mm.png " + camera + "/004_2mm.png --out", 0), 0u)
      << command;
  EXPECT_EQ(command.find("000_0mm.png"), std::string::npos) << command;
  EXPECT_EQ(command.find("001_0mm.png"), std::string::npos) << command;
  EXPECT_NE(scale.find("lowering_starts_at = 002_0mm.png"), std::string::npos) << scale;
  EXPECT_TRUE(fs::exists(dir / "camera" / "000_0mm.png"));  // every snapshot is still drawn
}

}  // namespace
}  // namespace trapdem
