#pragma once
// The study report: DIR/report/index.html with its figures beside it (no network, no script), and
// the same numbers for machines (summary.json, metrics.csv). Sections: findings (study_findings), the
// Figure-7-style panel of maximum shear strain at the final displacement on one colour scale (a run
// without snapshots drawn from its stored field history), vertical
// displacement contours at report.contours_at (a run without snapshots: the figures its own analysis
// drew, said as such), the ground reaction curves on one plot, the metrics
// table (each metric as mean and spread over the case's replicates), the sinkhole estimates, the parameters that differ, and each run's cost.
#include <filesystem>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "analysis/analysis_run.hpp"
#include "plot/figure_format.hpp"
#include "plot/specimen_figures.hpp"
#include "study/case_summary.hpp"
#include "study/replicate_statistics.hpp"
#include "study/study_definition.hpp"

namespace trapdem {

// One run of a case: its only run, or one replicate (one packing seed).
struct StudyRunResult {
  CaseSummary summary;                               // summary.replicate / seed say which
  std::filesystem::path run_dir;
  bool analysed = false;
  const AnalysisResult* final_analysis = nullptr;    // at the final snapshot (null: not analysed)
  const AnalysisResult* contour_analysis = nullptr;  // at report.contours_at (null: no snapshot there)
  std::string missing_note;                          // why an analysis is missing
  // Without snapshots: the figures `trapdem analyze` drew for the run, kept in its analysis/
  // (stored_analysis.hpp); empty where there is none or where the report draws its own.
  std::filesystem::path stored_strain_figure, stored_displacement_figure;
  // Without snapshots: the final strain from its analysis/field_history.h5, for the panel (null:
  // none usable, or the report draws its own).
  std::shared_ptr<const plot::StoredStrainMap> stored_strain_map;
};

struct StudyCaseResult {
  CaseSummary summary;                               // the replicates' means (combine_replicates)
  CaseEnsemble ensemble;                             // the analysed replicates and their means
  std::vector<StudyRunResult> runs;                  // every run of the case, in seed order
  std::filesystem::path run_dir;                     // the case's folder
  std::filesystem::path figure_run;                  // the run the figures show (the first analysed)
  const AnalysisResult* final_analysis = nullptr;    // of figure_run (null: none analysed)
  const AnalysisResult* contour_analysis = nullptr;  // of figure_run at report.contours_at
  std::string missing_note;                          // why an analysis is missing, for the page
  // Where no run of the case has snapshots: the first analysed run's own figures (StudyRunResult),
  // shown in place of the panel's map and of the contours, each on its own colour scale.
  std::filesystem::path stored_strain_figure, stored_displacement_figure;
  // Where no run of the case has snapshots: the first analysed run's stored map, drawn in the panel.
  std::shared_ptr<const plot::StoredStrainMap> stored_strain_map;
  std::vector<std::pair<std::string, std::string>> parameters;  // figure_run's resolved configuration
  double element_confining = kMissing;               // Pa, of the element test's angles (report.element_test)
};

struct StudyReportInput {
  std::string study_name, description;
  std::string scale, scale_description;
  StudyReportSettings settings;
  std::vector<StudyCaseResult> cases;
  // The figures' format (`trapdem study --format`). The page shows PNG and SVG figures as they are;
  // a browser does not show a PDF as an image, so with PDF each figure is also written as a PNG
  // for the page, which links every image to its figure file.
  plot::FigureFormat format = plot::FigureFormat::png;
};

// The report's files for scripts: one row per run (case, label, seed, every metric), and the
// per-case spreads (case, label, metric, n, mean, sd, min, max).
std::string metrics_csv(const StudyReportInput& input);
std::string case_summary_csv(const StudyReportInput& input);

// Writes the report into `report_dir` (created). Every file is written atomically; images are written
// before the page that shows them. Returns the page's path.
std::filesystem::path write_study_report(const std::filesystem::path& report_dir, const StudyReportInput& input);

}  // namespace trapdem
