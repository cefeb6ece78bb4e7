#pragma once
// A calibration (`trapdem calibrate BASE.toml --vary KEY=V1,V2,... [--vary ...] --target PIV_DIR
// --at 10mm`): runs the grid of cases (every combination of the varied values) as a study, scores each against the PIV
// measurement with `compare` (RMS of w_DEM - w_PIV over the trapdoor displacement), and writes the
// ranked table, the best configuration and the error surface figure (docs/study.md).
#include <filesystem>
#include <string>
#include <vector>

#include "study/study_definition.hpp"

namespace trapdem {

struct CalibrateOptions {
  std::string base;                  // the configuration the grid varies
  std::vector<std::string> vary;     // "KEY=V1,V2,..." (TOML values), one per varied key
  std::string target;                // PIV folder (piv.h5 in model coordinates)
  std::string at;                    // trapdoor displacement to compare, e.g. "10mm"
  std::string out;                   // empty: trapdem-out/calibrate-<base name>
  std::string grid = "2mm";          // spacing of the common grid
  std::string piv_trapdoor;          // "X,Z": trapdoor centre in the PIV coordinates (see compare)
  std::string format = "png";        // the figures (error surface, comparison, report): png | svg | pdf
  int threads = 0;
  bool quiet = false;
  bool collect = false;              // run nothing: rank the finished grid (the Slurm report job, issue 16)
};

struct VariedKey {
  std::string key;                   // dotted configuration key
  std::vector<std::string> values;   // TOML text of each value
};

// Parses "KEY=V1,V2,..." (throws InputError naming the option).
VariedKey parse_vary(const std::string& text);

struct CalibrationRow {
  std::string case_name;
  std::vector<std::string> values;   // one per varied key
  double error = 0.0;                // RMS(w_DEM - w_PIV) / delta
  double bias = 0.0;                 // mean(w_DEM - w_PIV) / delta
  double coverage = 0.0;             // fraction of the common grid compared
  std::filesystem::path run_dir;
};

struct Calibration {
  std::vector<VariedKey> keys;
  std::vector<CalibrationRow> ranked;  // best (smallest error) first
  std::filesystem::path out;
  bool complete = false;               // false: interrupted before every case ran
};

// Runs, scores and writes calibration.csv, best.toml, error_surface.png (or .svg, .pdf: options.format),
// compare_best.png and the study report. With
// options.collect nothing runs: every case must have finished (InputError naming those that have not).
Calibration calibrate(const CalibrateOptions& options);

// The grid as the study it runs (one scale, "base": the configuration; a case per combination) and
// its folder, after the options' checks (--vary parsed, --target holding piv.h5): what
// `--submit slurm` and `--status` work on.
struct CalibrationGrid {
  std::vector<VariedKey> keys;
  StudyDefinition study;
  std::filesystem::path out;
};
CalibrationGrid calibration_grid(const CalibrateOptions& options);

}  // namespace trapdem
