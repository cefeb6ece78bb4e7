#pragma once
// A line chart of a few series against one x axis, with a legend: used for the ground reaction
// curve (trapdoor and base stress over geostatic stress against trapdoor displacement over B), the
// ground reaction curves of several runs (`trapdem figure --grc`), the element test's panels. The
// file's extension picks the format (canvas.hpp).
#include <cairo.h>

#include <filesystem>
#include <string>
#include <vector>

#include "plot/canvas.hpp"
#include "plot/colour_map.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

struct LineSeries {
  std::string name;
  std::vector<double> x, y;
  Rgb colour{0.1, 0.1, 0.1};
  bool dashed = false;
  double width = 2.0;
};

struct LineChart {
  std::string title, subtitle, x_label, y_label;
  std::vector<LineSeries> series;
  double y_min = 0.0;                 // the y range always contains y_min (0: the origin shows)
  std::vector<double> reference_y;    // horizontal reference lines (e.g. 1 = geostatic)
};

// Draws the chart (title block, axes, series, legend) into `area` of a canvas.
void draw_line_chart(cairo_t* cr, Rect area, const LineChart& chart);

// One chart as a figure, `width` x `height` layout units.
void write_line_chart(const std::filesystem::path& path, const LineChart& chart,
                      int width = static_cast<int>(kFigureWidth), int height = 470);

}  // namespace trapdem::plot
