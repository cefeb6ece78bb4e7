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

// The levels of a contour figure: as given (a list), at every multiple of a step, or automatic.
struct ContourLevels {
  std::vector<double> list;  // field units; used as given (sorted), when not empty
  double step = 0.0;         // field units; > 0 (and no list): every non-zero multiple of it in the range
};

// The levels for a field ranging over [lo, hi]: the list as given, else the multiples of the step
// strictly inside (lo, hi), else about `automatic_count` levels at a 1-2-5 step; 0 itself is never
// a level from a step or the automatic rule (it is the undeformed value). Throws InputError if the
// step would give more than 1000 levels.
std::vector<double> contour_levels(const ContourLevels& spec, double lo, double hi, int automatic_count = 8);

// A level's label: four significant digits at most, no trailing zeros.
std::string contour_label(double level, const std::vector<double>& levels);

struct ContourStyle {
  double coordinate_scale = 1000.0;  // grid coordinates (m) times this = frame units (mm)
  double line_width = 1.6;
  Rgb colour{0.1, 0.1, 0.1};
  double font_size = 18.0;    // kFontSmall less a little: the labels sit on the lines
  double min_label_length = 50.0;    // units of line needed for a label
};

// Returns how many labels were placed.
int draw_contours(cairo_t* cr, const PlotFrame& frame, const GridField& field, const std::vector<double>& levels,
                  const std::function<std::string(double)>& label, const ContourStyle& style);

}  // namespace trapdem::plot
