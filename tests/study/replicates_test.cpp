// Replicates: the seeds each case runs with (derived, explicit, which level decides), the study
// file's mistakes about them, the statistics of a case's replicates, and the trend rule of the
// findings on made-up numbers (a difference counts only beyond the seeds' spread).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/text_file.hpp"
#include "study/findings.hpp"
#include "study/replicate_statistics.hpp"
#include "study/replicates.hpp"
#include "study/study_definition.hpp"
#include "study_file.hpp"
#include "study/study_runner.hpp"

namespace fs = std::filesystem;
using namespace trapdem;

namespace {

using study_test::error_of;
using study_test::write_study;

const fs::path kPresets = fs::path(TRAPDEM_SOURCE_DIR) / "presets";

// Three levels: the study asks 3, the scale "few" asks 2, case "own" gives its seeds.
const char* kStudy = R"(name = "seeds"
replicates = 3
[scales.many]
preset = "tiny"
[scales.few]
preset = "tiny"
replicates = 2
[cases.plain]
label = "Plain"
[cases.own]
seeds = [40, 11]
[cases.reseeded.set.pluviation]
seed = 100
)";

}  // namespace

TEST(Replicates, DerivedSeedsAreTheCaseSeedAndTheNextOnes) {
  ReplicateRequest r;
  EXPECT_EQ(replicate_seeds(r, 7), (std::vector<std::uint64_t>{7}));  // not asked: the case's own seed
  r.count = 3;
  EXPECT_EQ(replicate_seeds(r, 7), (std::vector<std::uint64_t>{7, 8, 9}));
  EXPECT_EQ(replicate_seeds(r, 7), replicate_seeds(r, 7));  // the same every time
  r.seeds = {5, 1};
  r.count = 2;
  EXPECT_EQ(replicate_seeds(r, 7), (std::vector<std::uint64_t>{5, 1}));
  EXPECT_EQ(replicate_folder_name(12), "seed-12");
}

TEST(Replicates, TheCaseThenTheScaleThenTheStudyDecides) {
  const StudyDefinition s = load_study(write_study("seeds.toml", kStudy));
  EXPECT_EQ(case_replicates(s, s.cases[0], s.scale("many")).count, 3);  // the study's
  EXPECT_EQ(case_replicates(s, s.cases[0], s.scale("few")).count, 2);   // the scale's
  const ReplicateRequest& own = case_replicates(s, s.cases[1], s.scale("few"));
  EXPECT_EQ(own.count, 2);
  EXPECT_EQ(own.seeds, (std::vector<std::uint64_t>{40, 11}));
}

TEST(Replicates, EachRunHasItsSeedFolderAndResolvedSeed) {
  const StudyDefinition s = load_study(write_study("seeds.toml", kStudy));
  const fs::path out = "/nowhere/out";
  // tiny's pluviation.seed is 7: 7, 8, 9; a case that sets its own seed starts from it.
  const std::vector<CaseRun> plain = case_runs(s, s.cases[0], s.scale("many"), out, kPresets);
  ASSERT_EQ(plain.size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(plain[k].seed, 7 + k);
    EXPECT_TRUE(plain[k].replicate);
    EXPECT_EQ(plain[k].dir, out / "cases" / "plain" / fmt::format("seed-{}", 7 + k));
    EXPECT_EQ(plain[k].recipe.overrides.back(), fmt::format("pluviation.seed={}", 7 + k));
  }
  const std::vector<CaseRun> reseeded = case_runs(s, s.cases[2], s.scale("few"), out, kPresets);
  ASSERT_EQ(reseeded.size(), 2u);
  EXPECT_EQ(reseeded[0].seed, 100u);
  EXPECT_EQ(reseeded[1].seed, 101u);
  const std::vector<CaseRun> own = case_runs(s, s.cases[1], s.scale("many"), out, kPresets);
  ASSERT_EQ(own.size(), 2u);
  EXPECT_EQ(own[0].dir.filename(), "seed-40");
  EXPECT_EQ(own[1].dir.filename(), "seed-11");

  // Without replicates: one run in the case's folder with the configuration's own seed.
  const StudyDefinition single = load_study(write_study("single.toml", "[scales.s]\npreset = \"tiny\"\n[cases.a]\nlabel = \"A\"\n"));
  const std::vector<CaseRun> one = case_runs(single, single.cases[0], single.scales[0], out, kPresets);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_FALSE(one[0].replicate);
  EXPECT_EQ(one[0].seed, 7u);
  EXPECT_EQ(one[0].dir, out / "cases" / "a");
}

TEST(Replicates, MistakesNameTheFileLineAndKey) {
  const std::string base = "[scales.s]\npreset = \"tiny\"\n";
  std::string e = error_of(base + "[cases.a]\nreplicates = 0\n");
  EXPECT_NE(e.find("bad.toml:4"), std::string::npos) << e;
  EXPECT_NE(e.find("cases.a.replicates"), std::string::npos) << e;
  e = error_of("replicates = 2\nseeds = [1, 2, 1]\n" + base + "[cases.a]\n");
  EXPECT_NE(e.find("seeds"), std::string::npos) << e;
  EXPECT_NE(e.find("1 is given twice"), std::string::npos) << e;
  e = error_of(base + "replicates = 3\nseeds = [1, 2]\n[cases.a]\n");
  EXPECT_NE(e.find("scales.s.seeds"), std::string::npos) << e;
  EXPECT_NE(e.find("as many seeds as scales.s.replicates says (3), not 2"), std::string::npos) << e;
  e = error_of(base + "[cases.a]\nseeds = [-1]\n");
  EXPECT_NE(e.find("cases.a.seeds"), std::string::npos) << e;
  e = error_of(base + "[cases.a]\nseeds = []\n");
  EXPECT_NE(e.find("cases.a.seeds"), std::string::npos) << e;
  e = error_of(base + "[cases.a]\nreplicate = 2\n");  // a typo is an unknown key
  EXPECT_NE(e.find("cases.a.replicate"), std::string::npos) << e;
  EXPECT_NE(e.find("bad.toml:4"), std::string::npos) << e;
  e = error_of(base + "[report.element]\nparticles = 300\n[cases.a]\n");
  EXPECT_NE(e.find("report.element_test = true"), std::string::npos) << e;
}

// The upper bounds of docs/study.md, each just past its bound and at it.
TEST(Replicates, UpperBoundsNameTheKeyAndTheBound) {
  const std::string base = "[scales.s]\npreset = \"tiny\"\n";
  std::string e = error_of(base + "[cases.a]\nreplicates = 1001\n");
  EXPECT_NE(e.find("cases.a.replicates = 1001"), std::string::npos) << e;
  EXPECT_NE(e.find("in [1, 1000]"), std::string::npos) << e;
  EXPECT_EQ(error_of(base + "[cases.a]\nreplicates = 1000\n"), "(no error)");
  e = error_of(base + "[cases.a]\nseeds = [9007199254740992]\n");
  EXPECT_NE(e.find("cases.a.seeds"), std::string::npos) << e;
  EXPECT_NE(e.find("9007199254740991"), std::string::npos) << e;
  EXPECT_EQ(error_of(base + "[cases.a]\nseeds = [9007199254740991]\n"), "(no error)");
  std::string seeds = "0";
  for (int k = 1; k <= 1000; ++k) seeds += fmt::format(", {}", k);
  e = error_of(base + "[cases.a]\nseeds = [" + seeds + "]\n");
  EXPECT_NE(e.find("at most 1000 seeds (one whole run each), not 1001"), std::string::npos) << e;
  // Eleven cases of 1000 replicates: 11 000 runs at the scale.
  std::string cases;
  for (int k = 0; k < 11; ++k) cases += fmt::format("[cases.c{}]\nreplicates = 1000\n", k);
  e = error_of(base + cases);
  EXPECT_NE(e.find("scales.s"), std::string::npos) << e;
  EXPECT_NE(e.find("at most 10000 runs at a scale (cases times replicates), not 11000"), std::string::npos) << e;
  EXPECT_EQ(error_of(base + "replicates = 1000\n[cases.a]\nlabel = \"A\"\n[cases.b]\nlabel = \"B\"\n"), "(no error)");
  cases.clear();
  for (int k = 0; k < 1001; ++k) cases += fmt::format("[cases.c{}]\n", k);
  e = error_of(base + cases);
  EXPECT_NE(e.find("at most 1000 cases (a run each, each in the report), not 1001"), std::string::npos) << e;
  e = error_of(base + "[cases.a]\n[report]\ncontours_at = 11.0\n");
  EXPECT_NE(e.find("report.contours_at"), std::string::npos) << e;
  EXPECT_NE(e.find("in (0, 10]"), std::string::npos) << e;
  e = error_of(base + "[cases.a]\n[report]\nmax_strain = 1e3\n");
  EXPECT_NE(e.find("report.max_strain"), std::string::npos) << e;
  EXPECT_NE(e.find("in [0, 10]"), std::string::npos) << e;
}

TEST(ReplicateStatistics, MeanSampleStandardDeviationAndRange) {
  const Spread s = spread_of({1.0, 2.0, std::nan(""), 6.0});
  EXPECT_EQ(s.n, 3u);
  EXPECT_DOUBLE_EQ(s.mean, 3.0);
  EXPECT_DOUBLE_EQ(s.sd, std::sqrt((4.0 + 1.0 + 9.0) / 2.0));  // n - 1 in the denominator
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 6.0);
  const Spread one = spread_of({4.0});
  EXPECT_EQ(one.n, 1u);
  EXPECT_FALSE(one.has_sd());
  EXPECT_TRUE(std::isnan(one.sd));
  EXPECT_EQ(spread_of({}).n, 0u);
}

TEST(ReplicateStatistics, MeanCurveOnTheFirstCurvesPointsAsFarAsTheShortestReaches) {
  std::vector<double> x_out, y_out;
  mean_curve({{0.0, 0.1, 0.2, 0.3}, {0.0, 0.2}}, {{1.0, 0.8, 0.6, 0.5}, {1.0, 0.4}}, x_out, y_out);
  EXPECT_EQ(x_out, (std::vector<double>{0.0, 0.1, 0.2}));
  ASSERT_EQ(y_out.size(), 3u);
  EXPECT_DOUBLE_EQ(y_out[0], 1.0);
  EXPECT_DOUBLE_EQ(y_out[1], 0.5 * (0.8 + 0.7));  // the second curve interpolated at 0.1
  EXPECT_DOUBLE_EQ(y_out[2], 0.5 * (0.6 + 0.4));
}

// The replicates' shapes: the common one of those known, else how many are columnar.
TEST(ReplicateStatistics, TheShapeIsTheReplicatesOwnWhereTheyAgree) {
  const auto combined = [](std::vector<std::string> shapes) {
    std::vector<CaseSummary> r(shapes.size());
    for (std::size_t k = 0; k < shapes.size(); ++k) r[k].shape = shapes[k];
    return combined_shape(r);
  };
  EXPECT_EQ(combined({"columnar", "columnar", "columnar"}), "columnar");
  EXPECT_EQ(combined({"elliptical", "unknown", "elliptical"}), "elliptical");
  EXPECT_EQ(combined({"columnar", "elliptical", "columnar"}), "mixed (2 of 3 columnar)");
  EXPECT_EQ(combined({"columnar", "", "elliptical"}), "mixed (1 of 2 columnar)");
  EXPECT_EQ(combined({"unknown", ""}), "unknown");
}

TEST(ReplicateStatistics, TheCaseIsTheMeanOfItsReplicates) {
  std::vector<CaseSummary> r(2);
  r[0].min_load_ratio = 0.2;
  r[1].min_load_ratio = 0.4;
  r[0].shape_ratio = 1.2;
  r[1].shape_ratio = 1.6;
  r[0].shape = "columnar";  // as each replicate's analysis called it
  r[1].shape = "elliptical";
  r[0].band_angle_deg = 5.0;  // the second found no band: the mean of those that did
  r[0].cost.wall_seconds = 10.0;
  r[1].cost.wall_seconds = 30.0;
  r[0].cost.particle_steps = 1e6;
  r[1].cost.particle_steps = 3e6;
  const CaseEnsemble e = make_ensemble(r);
  EXPECT_DOUBLE_EQ(e.mean.min_load_ratio, 0.3);
  EXPECT_DOUBLE_EQ(e.mean.band_angle_deg, 5.0);
  EXPECT_EQ(e.spread(&CaseSummary::band_angle_deg).n, 1u);
  EXPECT_EQ(e.mean.shape, "mixed (1 of 2 columnar)");  // not the shape of the mean shape ratio, 1.4
  EXPECT_DOUBLE_EQ(e.mean.cost.wall_seconds, 40.0);
  EXPECT_DOUBLE_EQ(e.mean.cost.particle_steps_per_second, 1e5);
  EXPECT_NEAR(e.spread(&CaseSummary::min_load_ratio).sd, std::sqrt(0.02), 1e-15);
}

namespace {

const std::vector<std::string> kLabels = {"Calibrated", "RF1", "RF2"};

Spread made_up(double mean, double sd, std::size_t n = 3) {
  Spread s;
  s.n = n;
  s.mean = mean;
  s.sd = n >= 2 ? sd : std::nan("");
  s.min = mean - sd;
  s.max = mean + sd;
  return s;
}

std::string trend(const std::vector<Spread>& v, double tolerance = 1.0) {
  return describe_trend("The band angle", kLabels, v, tolerance, [](double x) { return fmt::format("{:.1f}°", x); });
}

}  // namespace

// The rule: two cases differ when their means differ by more than max(resolution, sd_a + sd_b).
TEST(TrendRule, DifferenceOfMeansAgainstTheSumOfStandardDeviations) {
  EXPECT_TRUE(differs_beyond_spread(made_up(10.0, 1.0), made_up(12.5, 1.0), 1.0));   // 2.5 > 2
  EXPECT_FALSE(differs_beyond_spread(made_up(10.0, 1.0), made_up(11.5, 1.0), 1.0));  // 1.5 < 2
  EXPECT_FALSE(differs_beyond_spread(made_up(10.0, 0.1), made_up(10.5, 0.1), 1.0));  // within the resolution
  EXPECT_TRUE(differs_beyond_spread(made_up(10.0, 0.0, 1), made_up(11.5, 0.0, 1), 1.0));  // single runs: resolution
  EXPECT_FALSE(differs_beyond_spread(made_up(10.0, 1.0), Spread{}, 1.0));            // a missing value never differs
}

TEST(TrendRule, ATrendBeyondTheSpreadIsSaidSo) {
  EXPECT_EQ(trend({made_up(20.0, 1.0), made_up(15.0, 1.5), made_up(8.0, 2.0)}),
            "The band angle falls from 20.0° ± 1.0° in Calibrated to 8.0° ± 2.0° in RF2, at every step of the case "
            "order, each step beyond the seed-to-seed spread.");
  // Falls at every step, first to last beyond the spread, the middle step not on its own.
  EXPECT_EQ(trend({made_up(20.0, 1.0), made_up(18.0, 1.5), made_up(8.0, 2.0)}),
            "The band angle falls from 20.0° ± 1.0° in Calibrated to 8.0° ± 2.0° in RF2, at every step of the case "
            "order, beyond the seed-to-seed spread from first to last (1 of 2 steps beyond it on their own).");
}

TEST(TrendRule, NoTrendBeyondTheSpreadIsSaidSo) {
  // The same means as a falling trend, but the seeds scatter more than the cases differ.
  EXPECT_EQ(trend({made_up(20.0, 4.0), made_up(15.0, 4.0), made_up(12.0, 4.0)}),
            "The band angle shows no trend beyond the seed-to-seed spread (12.0° ± 4.0° in RF2 to 20.0° ± 4.0° in "
            "Calibrated; no two cases' means differ by more than the sum of their standard deviations or 1.0°).");
  EXPECT_EQ(trend({made_up(10.0, 1.0), made_up(16.0, 1.0), made_up(10.5, 1.0)}),
            "The band angle ends within the seed-to-seed spread of where it starts (from 10.0° ± 1.0° in Calibrated to "
            "10.5° ± 1.0° in RF2), but some cases differ beyond it (lowest 10.0° ± 1.0° in Calibrated, highest 16.0° ± "
            "1.0° in RF1).");
}

TEST(TrendRule, SingleRunsKeepTheResolutionWording) {
  EXPECT_EQ(trend({made_up(20.0, 0.0, 1), made_up(15.0, 0.0, 1), made_up(12.0, 0.0, 1)}),
            "The band angle falls from 20.0° in Calibrated to 12.0° in RF2, at every step of the case order.");
}

TEST(Findings, WarningsAndBandAnglesWithTheirUncertainty) {
  std::vector<CaseSummary> runs(2);
  for (int k = 0; k < 2; ++k) {
    runs[k].label = "Calibrated";
    runs[k].replicate = true;
    runs[k].seed = 7 + k;
    runs[k].band_angle_left_deg = 2.0 + 2.0 * k;
    runs[k].band_angle_left_error_deg = 0.5;
  }
  runs[1].warnings = {"the zone of influence reaches the side walls"};
  CaseSummary single;
  single.label = "RF1";
  single.band_angle_left_deg = 6.0;
  single.band_angle_left_error_deg = 0.4;
  single.band_angle_right_deg = 7.0;
  single.band_angle_right_error_deg = 0.3;
  const std::vector<std::string> f = study_findings({make_ensemble(runs), make_ensemble({single})}, 30.0);
  EXPECT_EQ(f[0], "Warning (Calibrated, seed 8): the zone of influence reaches the side walls.");
  bool angles = false;
  for (const std::string& line : f)
    if (line.rfind("Band angles to the vertical", 0) == 0) {
      angles = true;
      EXPECT_NE(line.find("Calibrated 3.0 ± 1.4° (fit 0.5°) / —"), std::string::npos) << line;
      EXPECT_NE(line.find("RF1 6.0 ± 0.4° / 7.0 ± 0.3°"), std::string::npos) << line;
    }
  EXPECT_TRUE(angles);
}
