// `trapdem compare` (apps/compare_command.hpp) on a synthetic DEM run and a PIV folder whose field
// is 0.2 mm higher (2 % of the 10 mm trapdoor displacement): the error in the text and the JSON
// report, the figure at its default place (DEM_DIR/analysis/compare_<at>mm.png) or at --out.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "compare_case.hpp"
#include "compare_command.hpp"
#include "core/json.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

TEST(CompareCommand, ReportsTheErrorAndWritesTheFigure) {
  const test::CompareCase c = test::make_compare_case("trapdem-compare-command", 0.0002);
  CompareOptions o = c.options();
  testing::internal::CaptureStdout();
  EXPECT_EQ(app::run_compare(o), 0);
  const std::string text = testing::internal::GetCapturedStdout();
  EXPECT_NE(text.find("/ delta = 2.00 %"), std::string::npos) << text;
  EXPECT_TRUE(fs::exists(c.run / "analysis" / "compare_10mm.png"));
  o.out = (c.run / "compare.png").string();
  o.json = true;
  testing::internal::CaptureStdout();
  EXPECT_EQ(app::run_compare(o), 0);
  const Json j = Json::parse(testing::internal::GetCapturedStdout());
  EXPECT_NEAR(j["rms_over_delta"].as_number(), 0.02, 1e-6);
  EXPECT_EQ(j["figure"].as_string(), o.out);
  EXPECT_TRUE(fs::exists(c.run / "compare.png"));
}

}  // namespace
}  // namespace trapdem
