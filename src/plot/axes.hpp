#pragma once
// Axes: a pixel rectangle mapped to a data range, "nice" tick positions (1, 2, 5 x 10^k), the
// frame with ticks, tick labels and axis titles. The spatial figures pass lengths in mm, so the
// ticks read in mm.
#include <cairo.h>

#include <string>
#include <vector>

#include "plot/canvas.hpp"

namespace trapdem::plot {

struct Range1 {
  double lo = 0.0, hi = 1.0;
  double span() const { return hi - lo; }
};

class PlotFrame {
 public:
  PlotFrame(Rect pixels, Range1 x, Range1 y) : pixels_(pixels), x_(x), y_(y) {}
  double px(double x) const { return pixels_.x + (x - x_.lo) / x_.span() * pixels_.w; }
  double py(double y) const { return pixels_.bottom() - (y - y_.lo) / y_.span() * pixels_.h; }
  double scale_x() const { return pixels_.w / x_.span(); }  // pixels per data unit
  const Rect& pixels() const { return pixels_; }
  Range1 x_range() const { return x_; }
  Range1 y_range() const { return y_; }
  void clip(cairo_t* cr) const;  // restricts drawing to the frame (cairo_save first)

 private:
  Rect pixels_;
  Range1 x_, y_;
};

// Tick values in [lo, hi] at a step of 1, 2 or 5 x 10^k giving at most max_count ticks.
std::vector<double> nice_ticks(double lo, double hi, int max_count);
double nice_step(double span, int max_count);

// The top of a colour scale: the smallest of 1, 2, 2.5 or 5 x 10^k at or above `value` (values
// above it saturate); 1 if `value` is not positive (or NaN).
double nice_ceiling(double value);

// A number for a tick label: no trailing zeros, as many decimals as the step needs.
std::string format_tick(double value, double step);

struct AxesStyle {
  std::string x_label, y_label;
  int max_x_ticks = 8, max_y_ticks = 8;
  double font_size = 16.0;
  bool grid = false;  // light grid lines at the ticks
};

// Frame, ticks with labels, and axis titles around `frame`.
void draw_axes(cairo_t* cr, const PlotFrame& frame, const AxesStyle& style);

// The largest rectangle with the aspect ratio of (x span : y span) fitting in `space`, centred
// horizontally and top-aligned (equal scales on both axes, as a map of the box needs).
Rect fit_equal_aspect(Rect space, Range1 x, Range1 y);

}  // namespace trapdem::plot
