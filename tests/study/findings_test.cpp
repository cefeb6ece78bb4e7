// The report's sentences say what the numbers show: the direction of a change over the cases,
// whether it holds at every step, and no change where the differences are within the resolution.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "study/findings.hpp"
#include "study/parameter_differences.hpp"

using namespace trapdem;

namespace {

const std::vector<std::string> kLabels = {"Calibrated", "RF1", "RF2", "RF3"};

std::string trend(const std::vector<double>& v, double tolerance = 1.0) {
  return describe_trend("The band angle", kLabels, v, tolerance, [](double x) { return fmt::format("{:.1f}°", x); });
}

}  // namespace

TEST(Findings, FallsAtEveryStep) {
  EXPECT_EQ(trend({20.0, 15.0, 12.0, 8.0}),
            "The band angle falls from 20.0° in Calibrated to 8.0° in RF3, at every step of the case order.");
}

TEST(Findings, RisesButNotAtEveryStep) {
  EXPECT_EQ(trend({5.0, 9.0, 7.0, 12.0}),
            "The band angle rises from 5.0° in Calibrated to 12.0° in RF3, but not at every step (lowest 5.0° in "
            "Calibrated, highest 12.0° in RF3).");
}

TEST(Findings, WithinResolutionIsNoChange) {
  EXPECT_EQ(trend({10.0, 10.4, 9.8, 10.5}),
            "The band angle is about the same in every case (9.8° to 10.5°; differences up to 1.0° are within its "
            "resolution).");
}

TEST(Findings, EndsWhereItStartsButVaries) {
  EXPECT_EQ(trend({10.0, 15.0, 4.0, 10.5}),
            "The band angle ends about where it starts (from 10.0° in Calibrated to 10.5° in RF3) but varies between "
            "(lowest 4.0° in RF2, highest 15.0° in RF1).");
}

TEST(Findings, MissingValuesAreNamedAndLeftOut) {
  const double nan = std::nan("");
  EXPECT_EQ(trend({20.0, nan, 12.0, nan}),
            "The band angle falls from 20.0° in Calibrated to 12.0° in RF2, at every step of the case order. (Not "
            "measured in RF1 and RF3.)");
  EXPECT_EQ(trend({nan, nan, 3.0, nan}).rfind("The band angle is 3.0° in RF2, the only case", 0), 0u);
  EXPECT_EQ(trend({nan, nan, nan, nan}), "The band angle was not measured in any case.");
}

TEST(Findings, SinkholeSentenceCountsTheCasesWhereTheSuppositionIsLarger) {
  std::vector<CaseSummary> cases(3);
  const double dem[] = {10.0, 12.0, 20.0}, supposition[] = {14.0, 14.0, 14.0}, implied[] = {20.0, 24.0, 35.0};
  for (int k = 0; k < 3; ++k) {
    cases[k].label = kLabels[k];
    cases[k].dem_surface_diameter = dem[k];
    cases[k].supposition_surface_diameter = supposition[k];
    cases[k].angle_from_surface_deg = implied[k];
  }
  const std::vector<std::string> f = study_findings(cases, 30.0);
  EXPECT_EQ(f.back(),
            "With an angle of draw of 30° the scenario supposition gives a larger sinkhole than the DEM's surface zone "
            "of influence in 2 of 3 cases (supposition over DEM 0.70 to 1.40); the DEM surface zones imply angles of "
            "draw of 20.0° to 35.0°.");
}

// One run a case: the findings say before the trends that the packings' spread is not in them; with
// replicates the trend rule's sentence stands there instead, and a single case needs neither.
TEST(Findings, SingleRunsSayTheSpreadBetweenPackingsIsNotInTheTrends) {
  const std::string caveat = "Each case is one run, one packing: the changes below are judged against each "
                             "quantity's resolution alone, not against the spread between packings";
  auto has = [](const std::vector<std::string>& f, const std::string& start) {
    return std::any_of(f.begin(), f.end(), [&](const std::string& s) { return s.rfind(start, 0) == 0; });
  };
  std::vector<CaseSummary> cases(2);
  for (int k = 0; k < 2; ++k) cases[k].label = kLabels[k];
  EXPECT_TRUE(has(study_findings(cases, 30.0), caveat));
  EXPECT_FALSE(has(study_findings(std::vector<CaseSummary>(cases.begin(), cases.begin() + 1), 30.0), caveat));
  CaseSummary seed = cases[0];
  seed.replicate = true;
  const std::vector<CaseEnsemble> replicated = {make_ensemble({seed, seed}), make_ensemble({cases[1]})};
  const std::vector<std::string> f = study_findings(replicated, 30.0);
  EXPECT_FALSE(has(f, caveat));
  EXPECT_TRUE(has(f, "Values are means ± the sample standard deviation over each case's packing seeds"));
}

TEST(ParameterDifferences, OnlyKeysThatDifferInFirstSeenOrder) {
  const std::vector<std::vector<std::pair<std::string, std::string>>> configs = {
      {{"name", "\"a\""}, {"box.width", "0.25"}, {"contact.kinetic_friction", "0.18"}},
      {{"name", "\"b\""}, {"box.width", "0.25"}, {"contact.kinetic_friction", "0.5"}, {"contact.extra", "1"}},
  };
  const auto d = differing_parameters(configs);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0].key, "contact.kinetic_friction");
  EXPECT_EQ(d[0].values, (std::vector<std::string>{"0.18", "0.5"}));
  EXPECT_EQ(d[1].key, "contact.extra");
  EXPECT_EQ(d[1].values, (std::vector<std::string>{"—", "1"}));
}

TEST(Findings, ShapesGroupTheCases) {
  std::vector<CaseSummary> cases(4);
  const char* shapes[] = {"elliptical", "elliptical", "columnar", "unknown"};
  for (int k = 0; k < 4; ++k) {
    cases[k].label = kLabels[k];
    cases[k].shape = shapes[k];
  }
  EXPECT_EQ(describe_shapes(cases),
            "The zone of influence is elliptical in Calibrated and RF1 and columnar in RF2 (columnar: both shear bands "
            "within 10 deg of the vertical and traced to 90 % of the layer's height, or the zone's width at mid-height "
            "below 1.3 B; else elliptical). (Not measured in RF3.)");
  cases.resize(2);
  EXPECT_EQ(describe_shapes(cases).rfind("The zone of influence is elliptical in every case (", 0), 0u);
}
