// `trapdem sinkhole` (apps/sinkhole_command.hpp): the table and the JSON of the scenario supposition,
// and with --from a DEM run's estimate beside it, with the analysis' warnings.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "sinkhole_command.hpp"
#include "sinkhole_run_folder.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

TEST(SinkholeCommand, TableAndJson) {
  app::SinkholeOptions o;
  o.throat = "1";
  o.layers = {"4:45", "6:0", "3:60"};
  const std::string table = app::sinkhole_report(o);
  EXPECT_NE(table.find("19.39 m: very large"), std::string::npos) << table;
  o.json = true;
  const Json j = Json::parse(app::sinkhole_report(o));
  EXPECT_NEAR(j["surface_diameter_m"].as_number(), 19.392304845413264, 1e-9);
  EXPECT_EQ(j["size_class"].as_string(), "very large");
  EXPECT_EQ(j["layers"].size(), 3u);
}

TEST(SinkholeCommand, FromRun) {
  const test::ScratchDir dir = test::sinkhole_run_folder("command");
  app::SinkholeOptions o;
  o.from = dir.path().string();
  EXPECT_THROW(app::sinkhole_report(o), InputError);  // no angle: required
  o.layers = {"5:30"};
  EXPECT_THROW(app::sinkhole_report(o), InputError);  // thickness comes from the run
  o.layers = {":30"};
  o.throat = std::string("2");  // not `= "2"`: GCC 12's false -Wrestrict here (bug 105651)
  EXPECT_THROW(app::sinkhole_report(o), InputError);  // throat comes from the run
  o.throat.clear();
  const std::string text = app::sinkhole_report(o);
  EXPECT_NE(text.find("ratio supposition / mechanism = 1.17"), std::string::npos) << text;
  o.json = true;
  const Json j = Json::parse(app::sinkhole_report(o));
  EXPECT_NEAR(j["mechanism"]["surface_diameter_m"].as_number(), 8.0, 1e-12);
  EXPECT_NEAR(j["ratio_supposition_over_mechanism"].as_number(), (2.0 + 12.8 * test::kTan30) / 8.0, 1e-9);
}

// The analysis' side-wall warning travels with the run's estimate: a zone bounded by the box gives a
// DEM sinkhole size bounded by the box, and the reader must be told so beside the number.
TEST(SinkholeCommand, FromRunCarriesTheAnalysisWarnings) {
  const std::string warning = "the zone of influence reaches the left side wall";
  const test::ScratchDir dir = test::sinkhole_run_folder("warning", true, warning);
  app::SinkholeOptions o;
  o.from = dir.path().string();
  o.layers = {":30"};
  const std::string text = app::sinkhole_report(o);
  EXPECT_NE(text.find("WARNING: " + warning), std::string::npos) << text;
  o.json = true;
  const Json j = Json::parse(app::sinkhole_report(o));
  ASSERT_EQ(j["model"]["warnings"].size(), 1u);
  EXPECT_EQ(j["model"]["warnings"][0].as_string(), warning);
  const test::ScratchDir quiet = test::sinkhole_run_folder("nowarning");
  o.from = quiet.path().string();
  o.json = false;
  EXPECT_EQ(app::sinkhole_report(o).find("WARNING"), std::string::npos);
}
