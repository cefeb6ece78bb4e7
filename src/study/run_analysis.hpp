#pragma once
// The analysis of a run folder (or of LAMMPS/LIGGGHTS dumps with a geometry file): the options as
// `trapdem analyze` takes them, the run's geometry read through RunFolder, the analysis and its
// outputs (fields.h5 + fields.xmf, metrics.json, figures) in DIR/analysis/. The study report and
// the comparison with PIV call it too. With the fields at the last snapshot goes the field history
// (field_history.h5: every snapshot's fields on one grid).
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/analysis_run.hpp"
#include "analysis/field_history.hpp"
#include "experiment/experiment_config.hpp"
#include "plot/contour_plot.hpp"

namespace trapdem {

struct AnalyzeOptions {
  std::string dir;                         // the run folder
  std::string at;                          // "80mm"; empty: the last snapshot
  std::string reference = "0mm";
  std::string view = "front";              // front | all
  std::string front_depth;                 // empty: 1.5 largest diameters
  bool incremental = false;
  std::string grid;                        // empty: half the mean diameter
  double smoothing = ShearBandSettings{}.smoothing_diameters;  // strain smoothing length, in d (0: none)
  std::vector<std::string> dumps;          // LAMMPS/LIGGGHTS text dumps instead of DIR/snapshots.h5
  std::string displacements;               // "0mm,10mm,..." one per dump
  std::string config;                      // geometry; empty: DIR/resolved.toml
  std::string out;                         // empty: DIR/analysis
  bool no_figures = false;
  bool no_field_history = false;           // no analysis/field_history.h5
  std::string field_history_grid;          // its grid spacing; empty: one mean diameter
  std::string format = "png";              // figures: png | svg | pdf
  std::string contour_levels;              // settlement contour levels "1mm,2mm,5mm"; empty: automatic
  std::string contour_step;                // or a step "0.5mm"
  bool quiet = false;                      // no table on the terminal
};

// The settings the options describe (throws InputError on bad values).
AnalysisSettings analysis_settings(const AnalyzeOptions& options);

// The settlement contour levels --contour-levels / --contour-step describe (m; both empty:
// automatic). Throws InputError naming the option on a bad length, both given, or a step <= 0.
plot::ContourLevels contour_levels_option(const std::string& levels, const std::string& step);

// The analysis' view of a specimen read by the experiment's configuration reader.
SpecimenGeometry specimen_geometry(const ExperimentConfig& specimen);

// The geometry in a run's resolved.toml or a short file with [box] and [trapdoor] (RunFolder::read_specimen).
SpecimenGeometry load_specimen_geometry(const std::filesystem::path& config_file);

// Runs the analysis of one folder (no output written).
AnalysisResult analyze_directory(const AnalyzeOptions& options);

// The fields at every snapshot after the reference on one grid (analysis/field_history.hpp), of
// DIR/snapshots.h5 or of the dumps.
FieldHistory field_history_of_directory(const AnalyzeOptions& options);

// Where the outputs go: options.out, else DIR/analysis.
std::filesystem::path analysis_output_dir(const AnalyzeOptions& options);

// The analysis with its outputs (fields, the field history unless no_field_history, metrics.json,
// figures unless no_figures, in options.format)
// written to analysis_output_dir(options); the files written go to `written_files` if given.
AnalysisResult analyze_and_write(const AnalyzeOptions& options, std::vector<std::filesystem::path>* written_files = nullptr);

}  // namespace trapdem
