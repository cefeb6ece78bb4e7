#include "plot/axes.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "plot/text.hpp"

namespace trapdem::plot {

void PlotFrame::clip(cairo_t* cr) const {
  cairo_rectangle(cr, pixels_.x, pixels_.y, pixels_.w, pixels_.h);
  cairo_clip(cr);
}

double nice_step(double span, int max_count) {
  if (!(span > 0.0) || max_count < 1) return 1.0;
  const double raw = span / max_count;
  const double power = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * power >= raw * (1.0 - 1e-9)) return m * power;
  }
  return 10.0 * power;
}

double nice_ceiling(double value) {
  if (!(value > 0.0)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(value)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * p >= value) return m * p;
  }
  return 10.0 * p;
}

std::vector<double> nice_ticks(double lo, double hi, int max_count) {
  std::vector<double> ticks;
  if (!(hi > lo)) return ticks;
  const double step = nice_step(hi - lo, max_count);
  const double eps = 1e-9 * step;
  for (double k = std::ceil((lo - eps) / step); k * step <= hi + eps; k += 1.0) {
    const double v = k * step;
    ticks.push_back(std::abs(v) < eps ? 0.0 : v);
  }
  return ticks;
}

std::string format_tick(double value, double step) {
  int decimals = 0;
  if (step > 0.0 && step < 1.0) decimals = static_cast<int>(std::ceil(-std::log10(step) - 1e-9));
  if (std::abs(value) < 0.5 * step * 1e-6) value = 0.0;
  return fmt::format("{:.{}f}", value, std::clamp(decimals, 0, 6));
}

void draw_axes(cairo_t* cr, const PlotFrame& frame, const AxesStyle& style) {
  const Rect& r = frame.pixels();
  const double tick = 6.0;
  TextStyle label{.size = style.font_size};
  cairo_save(cr);
  const auto xt = nice_ticks(frame.x_range().lo, frame.x_range().hi, style.max_x_ticks);
  const auto yt = nice_ticks(frame.y_range().lo, frame.y_range().hi, style.max_y_ticks);
  if (style.grid) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_set_line_width(cr, 1.0);
    for (double v : xt) {
      cairo_move_to(cr, std::round(frame.px(v)) + 0.5, r.y);
      cairo_line_to(cr, std::round(frame.px(v)) + 0.5, r.bottom());
    }
    for (double v : yt) {
      cairo_move_to(cr, r.x, std::round(frame.py(v)) + 0.5);
      cairo_line_to(cr, r.right(), std::round(frame.py(v)) + 0.5);
    }
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.5);
  cairo_rectangle(cr, r.x, r.y, r.w, r.h);
  cairo_stroke(cr);
  cairo_set_line_width(cr, 1.2);
  const double xstep = xt.size() > 1 ? xt[1] - xt[0] : 1.0;
  const double ystep = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  double max_label_width = 0.0;
  for (double v : xt) {
    const double x = frame.px(v);
    cairo_move_to(cr, x, r.bottom());
    cairo_line_to(cr, x, r.bottom() + tick);
    cairo_stroke(cr);
    label.h = HAlign::centre;
    label.v = VAlign::top;
    draw_text(cr, format_tick(v, xstep), x, r.bottom() + tick + 3.0, label);
  }
  for (double v : yt) {
    const double y = frame.py(v);
    cairo_move_to(cr, r.x - tick, y);
    cairo_line_to(cr, r.x, y);
    cairo_stroke(cr);
    label.h = HAlign::right;
    label.v = VAlign::middle;
    const Rect b = draw_text(cr, format_tick(v, ystep), r.x - tick - 4.0, y, label);
    max_label_width = std::max(max_label_width, b.w);
  }
  TextStyle title{.size = style.font_size * 1.05};
  if (!style.x_label.empty()) {
    title.h = HAlign::centre;
    title.v = VAlign::top;
    draw_text(cr, style.x_label, r.x + 0.5 * r.w, r.bottom() + tick + 6.0 + 1.3 * style.font_size, title);
  }
  if (!style.y_label.empty()) {
    title.h = HAlign::centre;
    title.v = VAlign::bottom;
    title.angle_deg = 90.0;
    draw_text(cr, style.y_label, r.x - tick - 10.0 - max_label_width, r.y + 0.5 * r.h, title);
  }
  cairo_restore(cr);
}

Rect fit_equal_aspect(Rect space, Range1 x, Range1 y) {
  const double aspect = x.span() / y.span();
  double w = space.w, h = space.w / aspect;
  if (h > space.h) {
    h = space.h;
    w = h * aspect;
  }
  return {space.x + 0.5 * (space.w - w), space.y, w, h};
}

}  // namespace trapdem::plot
