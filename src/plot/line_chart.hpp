#pragma once
// A line chart of a few series against one x axis, with a legend: used for the ground reaction
// curve (trapdoor and base stress over geostatic stress against trapdoor displacement over B).
#include <filesystem>
#include <string>
#include <vector>

#include "plot/colour_map.hpp"

namespace trapdem::plot {

struct LineSeries {
  std::string name;
  std::vector<double> x, y;
  Rgb colour{0.1, 0.1, 0.1};
  bool dashed = false;
  double width = 2.5;
};

struct LineChart {
  std::string title, subtitle, x_label, y_label;
  std::vector<LineSeries> series;
  double y_min = 0.0;                 // the y range always contains y_min (0: the origin shows)
  std::vector<double> reference_y;    // horizontal reference lines (e.g. 1 = geostatic)
};

void write_line_chart_png(const std::filesystem::path& path, const LineChart& chart, int width = 1000,
                          int height = 700);

}  // namespace trapdem::plot
