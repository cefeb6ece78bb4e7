#pragma once
// `trapdem analyze DIR`: strain fields, vertical displacement grid, shear-band metrics and zone of
// influence of a run, written to DIR/analysis/ (fields.h5 + fields.xmf, metrics.json, figures),
// and a short metrics table on the terminal. `trapdem figure DIR...`: a panel of several runs'
// shear strain maps with one shared colour scale.
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/analysis_run.hpp"

namespace trapdem::app {

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
  bool quiet = false;                      // no table on the terminal
};

// The settings and geometry the options describe (throws InputError on bad values).
AnalysisSettings analysis_settings(const AnalyzeOptions& options);
SpecimenGeometry load_specimen_geometry(const std::filesystem::path& config_file);

// Runs the analysis of one folder (no output written).
AnalysisResult analyze_directory(const AnalyzeOptions& options);

// The analysis with its outputs (fields, metrics.json, figures unless no_figures) written to
// options.out (default DIR/analysis); the files written go to `written_files` if given.
AnalysisResult analyze_and_write(const AnalyzeOptions& options, std::vector<std::filesystem::path>* written_files = nullptr);

// The whole command: analysis, outputs, figures, table. Returns the exit code.
int run_analyze(const AnalyzeOptions& options);

struct FigureOptions {
  std::vector<std::string> dirs;
  std::string out = "panel.png";
  std::string at;
  std::string reference = "0mm";
  std::string view = "front";
  std::string front_depth;
  double max_strain = 0.0;                 // colour scale top; 0: the largest of the runs' own
};

int run_figure(const FigureOptions& options);

// Splits "0mm, 10 mm,0.02" at commas and parses each as a length.
std::vector<double> parse_length_list(const std::string& text, const std::string& what);

}  // namespace trapdem::app
