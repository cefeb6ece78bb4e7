#pragma once
// The element test's figure: two panels against axial strain, the mobilised stress ratio
// sin phi' = (sigma_1 - sigma_3) / (sigma_1 + sigma_3) above and the volumetric strain below, one
// curve per specimen (dense solid, loose dashed), each panel a line chart (line_chart.hpp).
#include <filesystem>
#include <string>
#include <vector>

#include "plot/colour_map.hpp"

namespace trapdem::plot {

struct ElementCurve {
  std::string name;                          // legend entry, e.g. "dense, 50 kPa"
  std::vector<double> axial_strain;          // fraction
  std::vector<double> sin_phi;               // mobilised (sigma_1 - sigma_3) / (sigma_1 + sigma_3)
  std::vector<double> volumetric_strain;     // fraction, compression positive
  Rgb colour{0.1, 0.1, 0.1};
  bool dashed = false;
};

// Writes the two-panel figure (the extension picks the format); `reference_sin_phi` draws horizontal lines in the upper panel (e.g.
// sin 15.7 deg, the glass beads' critical state in the seed's Table 1).
void write_element_figure(const std::filesystem::path& path, const std::string& title, const std::string& subtitle,
                              const std::vector<ElementCurve>& curves, const std::vector<double>& reference_sin_phi);

}  // namespace trapdem::plot
