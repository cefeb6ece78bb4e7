#pragma once
// A study case's virtual element test (`[report] element_test = true`, issue 17): the particles and
// contact law of the case's configuration, sheared as `trapdem element` shears them
// (experiment/element_test.hpp), once per case (the packing seed of a trapdoor run does not enter),
// in cases/<name>/element/. Its phi'_peak and phi'_cs go beside the case's mechanism metrics.
#include <filesystem>
#include <string>
#include <vector>

#include "experiment/element_config.hpp"
#include "study/case_summary.hpp"
#include "study/study_definition.hpp"

namespace trapdem {

struct CaseElementTest {
  ElementSetup setup;
  std::string resolved;                // the configuration it runs (resolved.toml beside element.json)
};

// The case's configuration (`base` with the recipe's overrides) with [report.element]'s keys as
// `element.*` overrides, read by the element test's own strict reader. Throws InputError naming
// the case.
CaseElementTest case_element_test(const StudyCase& study_case, const std::filesystem::path& base,
                                  const ConfigRecipe& recipe, const StudyReportSettings& report);

// Whether `dir` holds a finished test of this configuration (a re-run of the study skips it).
bool element_test_finished(const CaseElementTest& test, const std::filesystem::path& dir);

// Runs the test afresh into `dir` (element.csv, element.json, element.log, and resolved.toml last:
// it marks the test finished). `threads` > 0 sets the OpenMP threads for the test (restored after).
void run_case_element_test(const CaseElementTest& test, const std::filesystem::path& dir, int threads);

// The material's angles read back from dir/element.json, at its first confining stress (NaN if the
// folder holds no finished test).
struct CaseElementAngles {
  double confining = kMissing;         // Pa
  double phi_peak_deg = kMissing;
  double phi_cs_deg = kMissing;
};
CaseElementAngles read_case_element_angles(const std::filesystem::path& dir);

}  // namespace trapdem
