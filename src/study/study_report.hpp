#pragma once
// The study report: DIR/report/index.html with its figures beside it (no network, no script), and
// the same numbers for machines (summary.json, metrics.csv). Sections: findings (study_findings), the
// Figure-7-style panel of maximum shear strain at the final displacement on one colour scale, vertical
// displacement contours at report.contours_at, the ground reaction curves on one plot, the metrics
// table, the sinkhole estimates, the parameters that differ, and each run's cost.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "analysis/analysis_run.hpp"
#include "study/case_summary.hpp"
#include "study/study_definition.hpp"

namespace trapdem {

struct StudyCaseResult {
  CaseSummary summary;
  std::filesystem::path run_dir;
  const AnalysisResult* final_analysis = nullptr;    // at the final snapshot (null: not analysed)
  const AnalysisResult* contour_analysis = nullptr;  // at report.contours_at (null: no snapshot there)
  std::string missing_note;                          // why an analysis is missing, for the page
  std::vector<std::pair<std::string, std::string>> parameters;  // resolved configuration, flattened
};

struct StudyReportInput {
  std::string study_name, description;
  std::string scale, scale_description;
  StudyReportSettings settings;
  std::vector<StudyCaseResult> cases;
};

// Writes the report into `report_dir` (created). Every file is written atomically; images are written
// before the page that shows them. Returns the page's path.
std::filesystem::path write_study_report(const std::filesystem::path& report_dir, const StudyReportInput& input);

}  // namespace trapdem
