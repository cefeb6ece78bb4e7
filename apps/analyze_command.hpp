#pragma once
// `trapdem analyze DIR`: strain fields, vertical displacement grid, shear-band metrics and zone of
// influence of a run, written to DIR/analysis/ (fields.h5 + fields.xmf, metrics.json, figures),
// and a short metrics table on the terminal. `trapdem figure DIR...`: a panel of several runs'
// shear strain maps with one shared colour scale; `trapdem figure --grc DIR...`: their ground
// reaction curves on one chart. The --out file's extension picks the format (png, svg, pdf).
#include <filesystem>
#include <string>
#include <vector>

#include "study/run_analysis.hpp"
#include "study/strain_panel_of_runs.hpp"

namespace trapdem::app {

// The whole command: analysis, outputs, figures, table. Returns the exit code.
int run_analyze(const AnalyzeOptions& options);

struct FigureOptions {
  std::vector<std::string> dirs;
  std::string out;                         // empty: panel.png (grc.png with --grc)
  bool grc = false;                        // the ground reaction curves instead of the strain panel
  RunPanelOptions panel;                   // the panel's; its labels are the curves' legend too
};

int run_figure(const FigureOptions& options);

}  // namespace trapdem::app
