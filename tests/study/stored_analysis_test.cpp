// The analysis a finished run keeps after its snapshots are gone (study/stored_analysis.hpp): taken
// when it is the report's own analysis, refused with the key named when any input differs. The
// folder is made by hand: resolved.toml with the trapdoor's travel (3 mm) and a metrics.json with the
// inputs the analysis writes for 2 mm beads (1.5 x 2.1 mm front depth, half of 2.0 mm grid).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/field_history.hpp"
#include "analysis/field_smoothing.hpp"
#include "study/stored_analysis.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace trapdem;
using trapdem::test::ScratchDir;

namespace {

// Each input as the report's analysis writes it; a test replaces one.
struct Inputs {
  std::string at_m = "0.00300002";
  std::string at_requested_m = "null";
  std::string reference_requested_m = "0";
  std::string view = "\"front\"";
  std::string front_depth_m = "0.00315";    // 1.5 x max_diameter_m
  std::string incremental = "false";
  std::string grid_spacing_m = "0.001";     // 0.5 x mean_diameter_m
  std::string smoothing_diameters = "2";
};

// The run folder, made by hand in a scratch folder of its own (removed with the value returned).
ScratchDir run_folder(const Inputs& in) {
  ScratchDir dir("trapdem-stored-analysis");
  fs::create_directories(dir / "analysis");
  std::ofstream(dir / "resolved.toml") << "name = \"hand\"\n[box]\nwidth = 0.1\ndepth = 0.01\nheight = 0.1\n"
                                          "[trapdoor]\nwidth = 0.02\ncentre = 0.05\ntravel = 0.003\n";
  std::ofstream(dir / "analysis" / "metrics.json")
      << "{\"inputs\": {\"at_m\": " << in.at_m << ", \"reference_m\": 0, \"at_requested_m\": " << in.at_requested_m
      << ", \"reference_requested_m\": " << in.reference_requested_m << ", \"view\": " << in.view
      << ", \"front_depth_m\": " << in.front_depth_m << ", \"incremental\": " << in.incremental
      << ", \"grid_spacing_m\": " << in.grid_spacing_m
      << ", \"at_snapshot\": \"000003\", \"reference_snapshot\": \"000001\"},\n"
      << " \"particles\": {\"mean_diameter_m\": 0.002, \"max_diameter_m\": 0.0021},\n"
      << " \"trapdoor\": {\"centre_x_m\": 0.05, \"width_m\": 0.02, \"travel_m\": 0.003},\n"
      << " \"shear_bands\": {\"smoothing_diameters\": " << in.smoothing_diameters << ", \"smoothing_m\": 0.004,"
      << " \"left\": {\"trace\": {\"z_m\": [0.001, 0.003], \"x_m\": [0.04, 0.041]},"
      << " \"branches\": [{\"trace\": {\"z_m\": [0.003, 0.005], \"x_m\": [0.041, 0.038]}}]},"
      << " \"right\": {\"trace\": {\"z_m\": [0.001], \"x_m\": [0.06]}, \"branches\": []}},\n"
      << " \"zone_of_influence\": {\"surface_width_m\": 0.04}}\n";
  return dir;
}

std::string refusal(const Inputs& in) {
  const ScratchDir dir = run_folder(in);
  const StoredAnalysis s = stored_final_analysis(RunFolder(dir.path()));
  EXPECT_FALSE(s.metrics.has_value()) << s.note;
  return s.note;
}

}  // namespace

TEST(StoredAnalysis, TheReportsOwnAnalysisIsTakenAndSaysWhereTheNumbersCameFrom) {
  const ScratchDir scratch = run_folder(Inputs{});
  const fs::path& dir = scratch.path();
  const StoredAnalysis s = stored_final_analysis(RunFolder(dir));
  ASSERT_TRUE(s.metrics.has_value()) << s.note;
  EXPECT_EQ((*s.metrics)["zone_of_influence"]["surface_width_m"].as_number(), 0.04);
  EXPECT_EQ(s.note, "no figures: snapshots.h5 is gone; the numbers are from " + (dir / "analysis" / "metrics.json").string());
}

// A study's report names the files from the study folder: a published report is read elsewhere.
// A folder that does not hold the run leaves the names as they are.
TEST(StoredAnalysis, TheNoteNamesFilesFromTheFolderItIsGiven) {
  const ScratchDir scratch = run_folder(Inputs{});
  const fs::path& dir = scratch.path();
  std::ofstream(dir / "analysis" / "shear_strain.png") << "png";
  StoredAnalysis s = stored_final_analysis(RunFolder(dir), dir.parent_path());
  ASSERT_TRUE(s.metrics.has_value()) << s.note;
  const fs::path from_parent = dir.filename() / "analysis";
  EXPECT_EQ(s.note, "snapshots.h5 is gone; the numbers are from " + (from_parent / "metrics.json").string() +
                        ", the figures are the run's own from " + from_parent.string());
  s = stored_final_analysis(RunFolder(dir), dir / "elsewhere");
  EXPECT_NE(s.note.find("the numbers are from " + (dir / "analysis" / "metrics.json").string()), std::string::npos)
      << s.note;
}

// The figures `trapdem analyze` drew with the metrics are the run's only pictures once its snapshots
// are gone: found as a page shows them (PNG, else SVG; a PDF is no image for a page), and named in
// the note.
TEST(StoredAnalysis, TheRunsOwnFiguresAreFoundBesideItsMetrics) {
  const ScratchDir scratch = run_folder(Inputs{});
  const fs::path& dir = scratch.path();
  const fs::path analysis = dir / "analysis";
  std::ofstream(analysis / "shear_strain.svg") << "<svg/>";
  std::ofstream(analysis / "shear_strain.png") << "png";
  std::ofstream(analysis / "vertical_displacement.svg") << "<svg/>";
  StoredAnalysis s = stored_final_analysis(RunFolder(dir));
  ASSERT_TRUE(s.metrics.has_value()) << s.note;
  EXPECT_EQ(s.strain_figure, analysis / "shear_strain.png");
  EXPECT_EQ(s.displacement_figure, analysis / "vertical_displacement.svg");
  EXPECT_EQ(s.note, "snapshots.h5 is gone; the numbers are from " + (analysis / "metrics.json").string() +
                        ", the figures are the run's own from " + analysis.string());
  fs::remove(analysis / "shear_strain.png");
  fs::remove(analysis / "shear_strain.svg");
  fs::remove(analysis / "vertical_displacement.svg");
  std::ofstream(analysis / "shear_strain.pdf") << "%PDF";
  s = stored_final_analysis(RunFolder(dir));
  EXPECT_TRUE(s.strain_figure.empty());
  EXPECT_TRUE(s.displacement_figure.empty());
  EXPECT_EQ(s.note.rfind("no figures: ", 0), 0u) << s.note;
}

TEST(StoredAnalysis, AnyOtherAnalysisIsRefusedNamingTheKey) {
  struct Change {
    std::string Inputs::*input;
    std::string value;
    std::string named;  // what the note says after "is another analysis than the report's: "
  };
  const Change changes[] = {
      {&Inputs::at_requested_m, "0.002", "inputs.at_requested_m (0.002; the report analyses the last snapshot)"},
      {&Inputs::reference_requested_m, "0.001", "inputs.reference_requested_m (0.001;"},
      {&Inputs::view, "\"all\"", "inputs.view (expected \"front\")"},
      {&Inputs::incremental, "true", "inputs.incremental"},
      {&Inputs::front_depth_m, "0.005", "inputs.front_depth_m"},
      {&Inputs::grid_spacing_m, "0.002", "inputs.grid_spacing_m"},
      {&Inputs::smoothing_diameters, "0", "shear_bands.smoothing_diameters (expected the default 2)"},
      // Written at 2 mm of a run that then went on to 3 mm: not the last snapshot.
      {&Inputs::at_m, "0.002", "inputs.at_m (2 mm; the run ends at 3 mm)"},
  };
  for (const Change& change : changes) {
    Inputs in;
    in.*change.input = change.value;
    const std::string note = refusal(in);
    EXPECT_NE(note.find("is another analysis than the report's: " + change.named), std::string::npos) << note;
  }
  Inputs within;  // the analysis' own tolerance: 2 % of 3 mm
  within.at_m = "0.00306";
  const ScratchDir scratch = run_folder(within);
  const fs::path& dir = scratch.path();
  EXPECT_TRUE(stored_final_analysis(RunFolder(dir)).metrics.has_value());
}

TEST(StoredAnalysis, AMissingOrBrokenFileIsANoteNotACrash) {
  const ScratchDir scratch = run_folder(Inputs{});
  const fs::path& dir = scratch.path();
  const fs::path metrics = dir / "analysis" / "metrics.json";
  std::ofstream(metrics) << "{\"inputs\": ";
  StoredAnalysis s = stored_final_analysis(RunFolder(dir));
  EXPECT_FALSE(s.metrics.has_value());
  EXPECT_NE(s.note.find(metrics.string() + " cannot be read: " + metrics.string()), std::string::npos) << s.note;
  fs::remove(metrics);
  s = stored_final_analysis(RunFolder(dir));
  EXPECT_FALSE(s.metrics.has_value());
  EXPECT_EQ(s.note, "not analysed: snapshots.h5 is missing and so is " + metrics.string());
}

// The report's panel draws a run without snapshots from its analysis/field_history.h5: the last
// layer, when it is the metrics' snapshot from the metrics' reference, smoothed at the metrics'
// length (the analysis smooths the triangles so), with the box from resolved.toml and the trapdoor
// and band traces from metrics.json. Another analysis's file, or none, leaves the numbers and
// says why there is no map.
TEST(StoredAnalysis, TheFieldHistorysLastLayerIsThePanelsMap) {
  const ScratchDir scratch = run_folder(Inputs{});
  const fs::path& dir = scratch.path();
  StoredAnalysis s = stored_final_analysis(RunFolder(dir));
  ASSERT_TRUE(s.metrics.has_value()) << s.note;
  EXPECT_FALSE(s.strain_map.has_value());
  EXPECT_EQ(s.strain_map_note, (dir / "analysis" / "field_history.h5").string() + " is missing");

  FieldHistory h;
  h.case_name = "hand";
  h.view = "front";
  h.front_depth = 0.00315;
  h.mean_diameter = 0.002;
  h.grid = GridSpec{0.001, 0.001, 0.002, 6, 4};
  h.reference_label = "000001";
  h.labels = {"000002", "000003"};
  h.trapdoor_displacement = {0.0015, 0.003};
  h.matched_particles = {100, 100};
  for (FloatStack* stack : {&h.vertical_displacement, &h.gamma_max, &h.volumetric_strain}) {
    stack->layers = 2, stack->rows = 4, stack->columns = 6;
    for (int k = 0; k < 48; ++k) stack->value.push_back(k < 24 ? -1.0f : 0.01f * static_cast<float>(k * k % 17));
  }
  h.gamma_max.value[24 + 5] = std::nanf("");
  write_field_history(dir / "analysis" / "field_history.h5", h);
  s = stored_final_analysis(RunFolder(dir));
  ASSERT_TRUE(s.strain_map.has_value()) << s.strain_map_note;
  const plot::StoredStrainMap& m = *s.strain_map;
  GridField last{h.grid, {}};
  for (int k = 24; k < 48; ++k) last.value.push_back(h.gamma_max.value[static_cast<std::size_t>(k)]);
  const GridField expected = smooth_grid_field(last, 0.004);
  ASSERT_EQ(m.gamma_max.value.size(), expected.value.size());
  for (std::size_t k = 0; k < expected.value.size(); ++k) {
    if (std::isnan(expected.value[k])) EXPECT_TRUE(std::isnan(m.gamma_max.value[k])) << k;
    else EXPECT_DOUBLE_EQ(m.gamma_max.value[k], expected.value[k]) << k;
  }
  EXPECT_EQ(m.gamma_max.grid.nx, 6u);
  EXPECT_EQ(m.box_width, 0.1);
  EXPECT_EQ(m.trapdoor.centre_x, 0.05);
  EXPECT_EQ(m.trapdoor.width, 0.02);
  EXPECT_EQ(m.travel, 0.003);
  EXPECT_EQ(m.mean_diameter, 0.002);
  EXPECT_EQ(m.smoothing_diameters, 2.0);
  ASSERT_EQ(m.band_traces.size(), 2u);
  ASSERT_EQ(m.band_traces[0].size(), 2u);
  EXPECT_EQ(m.band_traces[0][1].x, 0.041);
  EXPECT_EQ(m.band_traces[1].size(), 1u);
  ASSERT_EQ(m.branch_traces.size(), 1u);
  EXPECT_EQ(m.branch_traces[0][1].z, 0.005);

  // Another snapshot last (a history made before the run went on): no map, the numbers still taken.
  h.labels = {"000002", "000004"};
  write_field_history(dir / "analysis" / "field_history.h5", h);
  s = stored_final_analysis(RunFolder(dir));
  EXPECT_TRUE(s.metrics.has_value());
  EXPECT_FALSE(s.strain_map.has_value());
  EXPECT_NE(s.strain_map_note.find("is of another analysis than metrics.json (its last layer, snapshot 000004 from "
                                   "000001, front view; metrics.json: snapshot 000003 from 000001, front view)"),
            std::string::npos) << s.strain_map_note;
  std::ofstream(dir / "analysis" / "field_history.h5") << "not HDF5";
  s = stored_final_analysis(RunFolder(dir));
  EXPECT_TRUE(s.metrics.has_value());
  EXPECT_NE(s.strain_map_note.find("field_history.h5 cannot be read: "), std::string::npos) << s.strain_map_note;
}
