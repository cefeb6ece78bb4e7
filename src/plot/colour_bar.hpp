#pragma once
// A vertical colour bar: the map from lo (bottom) to hi (top) with ticks and a label on its right.
#include <cairo.h>

#include <string>

#include "plot/canvas.hpp"
#include "plot/colour_map.hpp"

namespace trapdem::plot {

struct ColourBarStyle {
  std::string label;          // drawn rotated along the bar's right side (wrapped to its length)
  double font_size = 15.0;
  int max_ticks = 6;
  double tick_scale = 1.0;    // tick labels show value * tick_scale (e.g. 1000 for mm)
  bool extend_high = false;   // values above hi are clipped: a triangle marks it on top
};

// `bar` is the coloured strip; ticks, numbers and label go to its right (about 5 font sizes, one
// more per extra line of the label).
void draw_colour_bar(cairo_t* cr, Rect bar, const ColourMap& map, double lo, double hi, const ColourBarStyle& style);

}  // namespace trapdem::plot
