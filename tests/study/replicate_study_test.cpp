// A tiny study of two cases with two packing seeds each and the element test: each replicate in its
// own folder with its seed in resolved.toml, the report's means and spreads equal to a hand
// computation from the replicates' own analyses, the findings' wording following the trend rule,
// the element test's angles in the metrics, a second call that runs nothing, and reports made after
// runs' snapshots were deleted.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "core/json.hpp"
#include "io/text_file.hpp"
#include "study_command.hpp"
#include "tiny_study.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

// The tiny pair of study_run_test.cpp (a shallow pour, 3 mm of travel), twice each, with
// restitution 0.9 (see tests/study/tiny_study.hpp). The element test is shrunk to 200 spheres sheared to 5 %
// (about ten seconds a case on one thread) at tiny's mid-depth stress, ~10 kPa.
const std::string kStudy = "name = \"tiny-seeds\"\ndescription = \"Two tiny cases, two packing seeds each\"\nreplicates = 2\n" +
                           test::tiny_scale("the tiny preset, a shallow pour and 3 mm of travel") +
                           test::three_mm_of_travel + "contact.restitution = 0.9\n[report]\ncontours_at = 0.002\n" +
                           test::small_element_test + test::smooth_and_rough_cases;

const char* kCases[] = {"smooth", "rough"};
const int kSeeds[] = {7, 8};  // tiny's pluviation.seed is 7: 7 and 7 + 1

Json read_json(const fs::path& file) { return Json::parse(read_text_file(file), file.string()); }

// The study's folder (one study for all the checks: it is a minute of running), removed at the
// process's exit.
const fs::path& study_dir() {
  static const test::ScratchDir dir("trapdem-replicate-study");
  return dir.path();
}
app::StudyOptions options() {
  app::StudyOptions o;
  o.file = (study_dir() / "study.toml").string();
  o.out = (study_dir() / "out").string();
  o.threads = 1;
  o.quiet = true;
  return o;
}
fs::path out() { return study_dir() / "out"; }
fs::path run_dir(int c, int s) { return out() / "cases" / kCases[c] / fmt::format("seed-{}", kSeeds[s]); }
Json summary() { return read_json(out() / "report" / "summary.json"); }

// Sample mean and standard deviation of two values, by hand.
double mean2(double a, double b) { return 0.5 * (a + b); }
double sd2(double a, double b) { return std::fabs(a - b) / std::sqrt(2.0); }

void EachReplicateRunsInItsFolderWithItsSeedInResolvedToml() {
  for (int c = 0; c < 2; ++c)
    for (int s = 0; s < 2; ++s) {
      const fs::path dir = run_dir(c, s);
      ASSERT_TRUE(fs::exists(dir / "run.json")) << dir;
      const std::string resolved = read_text_file(dir / "resolved.toml");
      const std::size_t pour = resolved.find("[pluviation]");
      ASSERT_NE(pour, std::string::npos);
      const std::size_t seed = resolved.find(fmt::format("\nseed = {}\n", kSeeds[s]), pour);
      EXPECT_NE(seed, std::string::npos) << resolved;
      EXPECT_LT(seed, resolved.find("\n[", pour + 1)) << "the seed is pluviation's";
    }
  // Different seeds, different packings: the two replicates of a case are not the same run.
  EXPECT_NE(read_text_file(run_dir(0, 0) / "trapdoor.csv"), read_text_file(run_dir(0, 1) / "trapdoor.csv"));
}

void MeansAndSpreadsEqualAHandComputationFromTheReplicatesAnalyses() {
  const Json s = summary();
  ASSERT_EQ(s["cases"].size(), 2u);
  const std::string case_csv = read_text_file(out() / "report" / "case_summary.csv");
  for (int c = 0; c < 2; ++c) {
    const Json& k = s["cases"][c];
    EXPECT_EQ(k["n"].as_number(), 2.0);
    ASSERT_EQ(k["runs"].size(), 2u);
    for (const char* key : {"surface_width_m", "mid_height_width_m"}) {
      double v[2];
      for (int r = 0; r < 2; ++r) {
        const Json m = read_json(run_dir(c, r) / "analysis" / "metrics.json");
        v[r] = json_number_or_nan(json_member_or_null(m, "zone_of_influence"), key);
        ASSERT_TRUE(std::isfinite(v[r])) << kCases[c] << " seed " << kSeeds[r] << " " << key;
        EXPECT_EQ(k["runs"][r]["seed"].as_number(), kSeeds[r]);
      }
      const std::string name = std::string(key) == "surface_width_m" ? "zone_surface_m" : "zone_mid_height_m";
      const Json& spread = k["spread"][name];
      EXPECT_EQ(spread["n"].as_number(), 2.0);
      EXPECT_NEAR(spread["mean"].as_number(), mean2(v[0], v[1]), 1e-15);
      EXPECT_NEAR(spread["sd"].as_number(), sd2(v[0], v[1]), 1e-15);
      EXPECT_EQ(spread["min"].as_number(), std::min(v[0], v[1]));
      EXPECT_EQ(spread["max"].as_number(), std::max(v[0], v[1]));
      EXPECT_NEAR(k[name].as_number(), mean2(v[0], v[1]), 1e-15);  // the case's value is the mean
      // case_summary.csv has the same numbers (6 significant digits).
      const std::string row_start = fmt::format("\n{},{},{},2,", kCases[c], c == 0 ? "Smooth" : "Rough", name);
      const std::size_t row = case_csv.find(row_start);
      ASSERT_NE(row, std::string::npos) << case_csv;
      std::istringstream fields(case_csv.substr(row + row_start.size(), case_csv.find('\n', row + 1) - row - row_start.size()));
      double mean = 0.0, sd = 0.0;
      char comma = 0;
      fields >> mean >> comma >> sd;
      EXPECT_NEAR(mean, mean2(v[0], v[1]), 1e-5 * std::fabs(mean));
      EXPECT_NEAR(sd, sd2(v[0], v[1]), 1e-5 * sd + 1e-12);
    }
  }
  // metrics.csv: one row per replicate, with its seed.
  const std::string csv = read_text_file(out() / "report" / "metrics.csv");
  for (int c = 0; c < 2; ++c)
    for (int r = 0; r < 2; ++r)
      EXPECT_NE(csv.find(fmt::format("\n{},{},{},", kCases[c], c == 0 ? "Smooth" : "Rough", kSeeds[r])), std::string::npos)
          << csv;
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 5);  // the header and four runs
}

void FindingsClaimADifferenceOnlyBeyondTheSpread() {
  const Json s = summary();
  const Json& smooth = s["cases"][0]["spread"]["min_load_ratio"];
  const Json& rough = s["cases"][1]["spread"]["min_load_ratio"];
  const double difference = std::fabs(rough["mean"].as_number() - smooth["mean"].as_number());
  const double spread = smooth["sd"].as_number() + rough["sd"].as_number();
  bool sentence = false, rule = false;
  for (std::size_t k = 0; k < s["findings"].size(); ++k) {
    const std::string f = s["findings"][k].as_string();
    rule = rule || f.rfind("Values are means ± the sample standard deviation", 0) == 0;
    if (f.rfind("The least trapdoor load", 0) != 0) continue;
    sentence = true;
    if (difference > std::max(0.02, spread)) {
      EXPECT_NE(f.find(rough["mean"].as_number() < smooth["mean"].as_number() ? "falls from" : "rises from"),
                std::string::npos) << f;
    } else {
      EXPECT_NE(f.find("shows no trend beyond the seed-to-seed spread"), std::string::npos)
          << f << " (difference " << difference << ", spread " << spread << ")";
    }
    EXPECT_NE(f.find(" ± "), std::string::npos) << f;
  }
  EXPECT_TRUE(sentence);
  EXPECT_TRUE(rule);
}

void TheElementTestsAnglesAreInTheMetrics() {
  const Json s = summary();
  const std::string csv = read_text_file(out() / "report" / "metrics.csv");
  EXPECT_NE(csv.substr(0, csv.find('\n')).find(",phi_peak_deg,phi_cs_deg,"), std::string::npos);
  for (int c = 0; c < 2; ++c) {
    const fs::path element = out() / "cases" / kCases[c] / "element";
    const Json e = read_json(element / "element.json");
    EXPECT_EQ(e["particles"].as_number(), 200.0);
    const double peak = e["angles"][0]["phi_peak_deg"].as_number(), cs = e["angles"][0]["phi_cs_deg"].as_number();
    EXPECT_GT(peak, 0.0);
    EXPECT_EQ(s["cases"][c]["phi_peak_deg"].as_number(), peak);
    EXPECT_EQ(s["cases"][c]["phi_cs_deg"].as_number(), cs);
    EXPECT_NE(csv.find(fmt::format(",{:.6g},{:.6g},", peak, cs)), std::string::npos) << csv;
    // Its configuration is the case's: the case's friction.
    EXPECT_NE(read_text_file(element / "resolved.toml").find(c == 0 ? "kinetic_friction = 0.2" : "kinetic_friction = 0.6"),
              std::string::npos);
  }
  bool sentence = false;
  for (std::size_t k = 0; k < s["findings"].size(); ++k)
    sentence = sentence || s["findings"][k].as_string().rfind("The virtual element test gives phi'_peak / phi'_cs", 0) == 0;
  EXPECT_TRUE(sentence);
  const std::string page = read_text_file(out() / "report" / "index.html");
  EXPECT_NE(page.find("φ'<sub>peak</sub>"), std::string::npos);
  EXPECT_NE(page.find("ground_reaction_smooth.png"), std::string::npos);
  EXPECT_TRUE(fs::exists(out() / "report" / "ground_reaction_rough.png"));
}

void ASecondCallSkipsEveryFinishedReplicateAndElementTest() {
  const std::string before = read_text_file(out() / "report" / "case_summary.csv");
  const auto element_time = fs::last_write_time(out() / "cases" / "smooth" / "element" / "element.json");
  ASSERT_EQ(app::run_study(options()), 0);
  const std::string log = read_text_file(out() / "study.log");
  int counter = 0;
  for (int c = 0; c < 2; ++c) {
    for (int s = 0; s < 2; ++s)
      EXPECT_NE(log.find(fmt::format("[{}/4] {} seed {}: finished before, skipped", ++counter, kCases[c], kSeeds[s])),
                std::string::npos) << log;
    EXPECT_NE(log.find(fmt::format("{} element test: finished before, skipped", kCases[c])), std::string::npos) << log;
  }
  EXPECT_EQ(fs::last_write_time(out() / "cases" / "smooth" / "element" / "element.json"), element_time);
  EXPECT_EQ(read_text_file(out() / "report" / "case_summary.csv"), before);
}

// Snapshots are most of a run's size and what gets deleted or left on the cluster; the light results
// keep analysis/metrics.json (and, published with --figures, the figures analyze drew). A report
// made without them takes each run's numbers from there (the same numbers), draws the run in the
// strain panel from its analysis/field_history.h5, shows the run's own figures where they are kept
// and says whose they are, or draws none and says why; a metrics.json
// of another analysis than the report's (here one at 2 mm of travel) is not taken for it: the run
// is left out, the key named.
void ARunWhoseSnapshotsAreGoneIsReportedFromItsStoredAnalysis() {
  const std::string before = read_text_file(out() / "report" / "case_summary.csv");
  for (int s = 0; s < 2; ++s) ASSERT_TRUE(fs::remove(run_dir(0, s) / "snapshots.h5"));
  app::StudyOptions report_only = options();
  report_only.report_only = true;
  ASSERT_EQ(app::run_study(report_only), 0);
  EXPECT_EQ(read_text_file(out() / "report" / "case_summary.csv"), before);
  const Json s = summary();
  for (int r = 0; r < 2; ++r) EXPECT_TRUE(s["cases"][0]["runs"][r]["analysed"].as_bool());
  std::string page = read_text_file(out() / "report" / "index.html");
  // The first seed's own figures, copied beside the page byte for byte, in place of the report's.
  for (const char* figure : {"shear_strain", "vertical_displacement"}) {
    const fs::path copy = out() / "report" / fmt::format("run_{}_smooth.png", figure);
    ASSERT_TRUE(fs::exists(copy)) << copy;
    EXPECT_EQ(read_text_file(copy), read_text_file(run_dir(0, 0) / "analysis" / fmt::format("{}.png", figure)));
    EXPECT_NE(page.find(fmt::format("<img src=\"run_{}_smooth.png\"", figure)), std::string::npos) << page;
  }
  EXPECT_NE(page.find("Smooth: the map its run's own analysis drew, on that figure's colour scale"),
            std::string::npos) << page;
  // Named from the study folder: the page is read where the machine's paths mean nothing.
  EXPECT_NE(page.find("the figures are the run&#39;s own from " +
                      (run_dir(0, 0) / "analysis").lexically_relative(out()).string()),
            std::string::npos) << page;
  EXPECT_EQ(page.find(out().string()), std::string::npos) << page;
  EXPECT_EQ(page.find("contours_smooth.png"), std::string::npos);
  EXPECT_NE(page.find("contours_rough.png"), std::string::npos);
  EXPECT_NE(page.find("strain_panel.png"), std::string::npos);
  // Smooth is in the panel too, drawn from its first seed's analysis/field_history.h5, and the
  // caption says so.
  EXPECT_NE(page.find("A map marked “stored grid” is of a run whose snapshots are gone"), std::string::npos) << page;
  EXPECT_EQ(page.find("not in the strain panel"), std::string::npos) << page;

  // Without the figures and the field histories too: no figure of Smooth, and the page says why.
  for (int r = 0; r < 2; ++r)
    for (const char* file : {"shear_strain.png", "vertical_displacement.png", "field_history.h5"})
      ASSERT_TRUE(fs::remove(run_dir(0, r) / "analysis" / file));
  std::ofstream(out() / "report" / "my_sketch.png") << "a reader's own file";
  ASSERT_EQ(app::run_study(report_only), 0);
  page = read_text_file(out() / "report" / "index.html");
  EXPECT_NE(page.find("Smooth: no figures: snapshots.h5 is gone; the numbers are from "), std::string::npos) << page;
  EXPECT_NE(page.find("field_history.h5 is missing"), std::string::npos) << page;
  EXPECT_EQ(page.find("A map marked “stored grid”"), std::string::npos) << page;
  EXPECT_EQ(page.find("run_shear_strain_smooth.png"), std::string::npos);
  // The copies the previous report made are gone with it (they would pass for this report's);
  // a file of another name stays.
  for (const char* figure : {"shear_strain", "vertical_displacement"})
    EXPECT_FALSE(fs::exists(out() / "report" / fmt::format("run_{}_smooth.png", figure))) << figure;
  EXPECT_TRUE(fs::exists(out() / "report" / "my_sketch.png"));
  EXPECT_TRUE(fs::exists(out() / "report" / "contours_rough.png"));

  const fs::path metrics = run_dir(1, 0) / "analysis" / "metrics.json";
  std::string text = read_text_file(metrics);
  const std::string final_snapshot = "\"at_requested_m\": null";
  ASSERT_NE(text.find(final_snapshot), std::string::npos) << text;
  text.replace(text.find(final_snapshot), final_snapshot.size(), "\"at_requested_m\": 0.002");
  std::ofstream(metrics) << text;
  ASSERT_TRUE(fs::remove(run_dir(1, 0) / "snapshots.h5"));
  ASSERT_EQ(app::run_study(report_only), 0);
  const Json t = summary();
  const Json& rough = t["cases"][1];
  EXPECT_EQ(rough["n"].as_number(), 1.0);
  EXPECT_FALSE(rough["runs"][0]["analysed"].as_bool());
  EXPECT_TRUE(rough["runs"][1]["analysed"].as_bool());
  const Json kept = read_json(run_dir(1, 1) / "analysis" / "metrics.json");
  EXPECT_EQ(rough["zone_surface_m"].as_number(),
            json_number_or_nan(json_member_or_null(kept, "zone_of_influence"), "surface_width_m"));
  page = read_text_file(out() / "report" / "index.html");
  EXPECT_NE(page.find("inputs.at_requested_m (0.002; the report analyses the last snapshot)"), std::string::npos)
      << page;
}

}  // namespace

// One study, run once (each check below would otherwise run it again: gtest_discover_tests runs
// every test in a process of its own), then checked, then called a second time.
TEST(ReplicateStudy, TwoCasesTwoSeedsAndTheElementTest) {
  std::ofstream(study_dir() / "study.toml") << kStudy;
  ASSERT_EQ(app::run_study(options()), 0);
  {
    SCOPED_TRACE("EachReplicateRunsInItsFolderWithItsSeedInResolvedToml");
    EachReplicateRunsInItsFolderWithItsSeedInResolvedToml();
  }
  {
    SCOPED_TRACE("MeansAndSpreadsEqualAHandComputationFromTheReplicatesAnalyses");
    MeansAndSpreadsEqualAHandComputationFromTheReplicatesAnalyses();
  }
  {
    SCOPED_TRACE("FindingsClaimADifferenceOnlyBeyondTheSpread");
    FindingsClaimADifferenceOnlyBeyondTheSpread();
  }
  {
    SCOPED_TRACE("TheElementTestsAnglesAreInTheMetrics");
    TheElementTestsAnglesAreInTheMetrics();
  }
  {
    SCOPED_TRACE("ASecondCallSkipsEveryFinishedReplicateAndElementTest");
    ASecondCallSkipsEveryFinishedReplicateAndElementTest();
  }
  {
    SCOPED_TRACE("ARunWhoseSnapshotsAreGoneIsReportedFromItsStoredAnalysis");
    ARunWhoseSnapshotsAreGoneIsReportedFromItsStoredAnalysis();
  }
}
