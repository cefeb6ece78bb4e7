#pragma once
// `trapdem figure DIR...`: several run folders' maximum shear strain maps side by side, on one
// colour scale and one length scale (plot::write_strain_panel), each run analysed in memory at the
// same trapdoor displacement, reference and view, as `trapdem analyze` would. What the command and
// the Python module's trapdem.figure share.
#include <filesystem>
#include <string>
#include <vector>

namespace trapdem {

struct RunPanelOptions {
  std::string at;                    // "80mm"; empty: each run's last snapshot
  std::string reference = "0mm";
  std::string view = "front";        // front | all
  std::string front_depth;           // empty: 1.5 largest diameters
  std::vector<std::string> labels;   // panel titles, one per run; empty: the runs' names
  double max_strain = 0.0;           // top of the gamma_max scale; 0: the largest of the runs' own
};

struct RunPanel {
  std::size_t runs = 0;
  double max_strain = 0.0;           // the scale drawn (given, or the largest automatic one)
};

// Writes the panel of `dirs` to `out` (its extension picks png, svg or pdf). Throws InputError
// before any analysis for no folder, a bad extension, labels not one per folder or a negative
// max_strain; then the analysis' errors naming the folder.
RunPanel write_strain_panel_of_runs(const std::filesystem::path& out, const std::vector<std::filesystem::path>& dirs,
                                    const RunPanelOptions& options = {});

}  // namespace trapdem
