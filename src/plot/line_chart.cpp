#include "plot/line_chart.hpp"

#include <algorithm>
#include <cmath>

#include "plot/axes.hpp"
#include "plot/canvas.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

void write_line_chart_png(const std::filesystem::path& path, const LineChart& chart, int width, int height) {
  double xlo = 0.0, xhi = 0.0, ylo = chart.y_min, yhi = chart.y_min;
  bool any = false;
  for (const auto& s : chart.series) {
    for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
      if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) continue;
      xlo = any ? std::min(xlo, s.x[k]) : s.x[k];
      xhi = any ? std::max(xhi, s.x[k]) : s.x[k];
      ylo = std::min(ylo, s.y[k]);
      yhi = std::max(yhi, s.y[k]);
      any = true;
    }
  }
  for (double y : chart.reference_y) yhi = std::max(yhi, y), ylo = std::min(ylo, y);
  if (!(xhi > xlo)) xhi = xlo + 1.0;
  if (!(yhi > ylo)) yhi = ylo + 1.0;
  const double ystep = nice_step(yhi - ylo, 8);
  ylo = std::floor(ylo / ystep) * ystep;
  yhi = std::ceil(yhi / ystep - 1e-3) * ystep;
  const double xstep = nice_step(xhi - xlo, 8);
  xhi = std::ceil(xhi / xstep - 1e-3) * xstep;

  Canvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  const Rect plot{100.0, 95.0, width - 140.0, height - 95.0 - 85.0};
  const PlotFrame f(plot, {xlo, xhi}, {ylo, yhi});
  AxesStyle axes{.x_label = chart.x_label, .y_label = chart.y_label, .grid = true};
  draw_axes(cr, f, axes);
  cairo_save(cr);
  f.clip(cr);
  for (double y : chart.reference_y) {
    cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
    cairo_set_line_width(cr, 1.2);
    const double dash[] = {2.0, 4.0};
    cairo_set_dash(cr, dash, 2, 0.0);
    cairo_move_to(cr, plot.x, f.py(y));
    cairo_line_to(cr, plot.right(), f.py(y));
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
  }
  for (const auto& s : chart.series) {
    set_colour(cr, s.colour);
    cairo_set_line_width(cr, s.width);
    cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
    const double dash[] = {9.0, 5.0};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0.0);
    bool pen = false;
    for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
      if (!std::isfinite(s.x[k]) || !std::isfinite(s.y[k])) {
        pen = false;
        continue;
      }
      if (!pen) cairo_move_to(cr, f.px(s.x[k]), f.py(s.y[k]));
      else cairo_line_to(cr, f.px(s.x[k]), f.py(s.y[k]));
      pen = true;
    }
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
  }
  cairo_restore(cr);
  // Legend, top right inside the frame.
  const TextStyle legend{.size = 15.0, .v = VAlign::middle};
  double widest = 0.0;
  for (const auto& s : chart.series) widest = std::max(widest, text_box(cr, s.name, legend).w);
  const double lw = widest + 70.0, lh = 26.0 * chart.series.size() + 12.0;
  // The first corner whose box no data point falls in: top right, bottom right, top left, middle right.
  auto data_inside = [&](const Rect& b) {
    for (const auto& s : chart.series) {
      for (std::size_t k = 0; k < s.x.size() && k < s.y.size(); ++k) {
        const double x = f.px(s.x[k]), y = f.py(s.y[k]);
        if (x >= b.x - 4 && x <= b.right() + 4 && y >= b.y - 4 && y <= b.bottom() + 4) return true;
      }
    }
    return false;
  };
  const std::vector<Rect> candidates{{plot.right() - lw - 12.0, plot.y + 12.0, lw, lh},
                                     {plot.right() - lw - 12.0, plot.bottom() - lh - 12.0, lw, lh},
                                     {plot.x + 12.0, plot.y + 12.0, lw, lh},
                                     {plot.right() - lw - 12.0, plot.y + 0.5 * (plot.h - lh), lw, lh}};
  Rect box = candidates.front();
  for (const Rect& c : candidates) {
    if (!data_inside(c)) {
      box = c;
      break;
    }
  }
  cairo_set_source_rgba(cr, 1, 1, 1, 0.92);
  cairo_rectangle(cr, box.x, box.y, box.w, box.h);
  cairo_fill_preserve(cr);
  cairo_set_source_rgb(cr, 0.6, 0.6, 0.6);
  cairo_set_line_width(cr, 1.0);
  cairo_stroke(cr);
  for (std::size_t k = 0; k < chart.series.size(); ++k) {
    const auto& s = chart.series[k];
    const double y = box.y + 19.0 + 26.0 * k;
    set_colour(cr, s.colour);
    cairo_set_line_width(cr, s.width);
    const double dash[] = {9.0, 5.0};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0.0);
    cairo_move_to(cr, box.x + 10.0, y);
    cairo_line_to(cr, box.x + 52.0, y);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    draw_text(cr, s.name, box.x + 60.0, y, legend);
  }
  draw_text(cr, chart.title, plot.x, 18.0, TextStyle{.size = 20.0, .bold = true, .v = VAlign::top});
  if (!chart.subtitle.empty()) {
    draw_text(cr, chart.subtitle, plot.x, 47.0, TextStyle{.size = 15.0, .colour = {0.3, 0.3, 0.3}, .v = VAlign::top});
  }
  canvas.write_png(path);
}

}  // namespace trapdem::plot
