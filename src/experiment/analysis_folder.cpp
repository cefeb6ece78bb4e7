#include "experiment/analysis_folder.hpp"

#include <cmath>

#include <fmt/format.h>

namespace trapdem {

std::filesystem::path AnalysisFolder::compare_png(double trapdoor_displacement) const {
  return dir_ / fmt::format("compare_{:g}mm.png", std::round(trapdoor_displacement * 1e4) / 10.0);
}

}  // namespace trapdem
