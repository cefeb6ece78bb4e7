#pragma once
// Contour lines of a grid field drawn on a plot frame, each labelled with its level on a white
// box where the line is long enough and the label does not overlap another one.
#include <cairo.h>

#include <functional>
#include <string>
#include <vector>

#include "analysis/grid_field.hpp"
#include "plot/axes.hpp"
#include "plot/colour_map.hpp"

namespace trapdem::plot {

struct ContourStyle {
  double coordinate_scale = 1000.0;  // grid coordinates (m) times this = frame units (mm)
  double line_width = 1.6;
  Rgb colour{0.1, 0.1, 0.1};
  double font_size = 13.0;
  double min_label_length = 60.0;    // pixels of line needed for a label
};

// Returns how many labels were placed.
int draw_contours(cairo_t* cr, const PlotFrame& frame, const GridField& field, const std::vector<double>& levels,
                  const std::function<std::string(double)>& label, const ContourStyle& style);

}  // namespace trapdem::plot
