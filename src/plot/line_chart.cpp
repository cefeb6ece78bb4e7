#include "plot/line_chart.hpp"

#include <algorithm>
#include <cmath>

#include "plot/axes.hpp"
#include "plot/canvas.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

void draw_line_chart(cairo_t* cr, Rect area, const LineChart& chart) {
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
  const double ystep = nice_step(yhi - ylo, 6);
  ylo = std::floor(ylo / ystep) * ystep;
  yhi = std::ceil(yhi / ystep - 1e-3) * ystep;
  const double xstep = nice_step(xhi - xlo, 6);
  xhi = std::ceil(xhi / xstep - 1e-3) * xstep;

  const double top = area.y + 10.0 + title_height(chart.title, chart.subtitle, kFontTitle, area.w - 20.0) + 8.0;
  const double left = 4.0 * kFontSmall, bottom = 3.6 * kFontSmall;
  const Rect plot{area.x + left, top, area.w - left - 1.6 * kFontSmall, area.bottom() - top - bottom};
  const PlotFrame f(plot, {xlo, xhi}, {ylo, yhi});
  AxesStyle axes{.x_label = chart.x_label, .y_label = chart.y_label, .max_x_ticks = 6, .max_y_ticks = 6,
                 .font_size = kFontSmall, .grid = true};
  draw_axes(cr, f, axes);
  cairo_save(cr);
  f.clip(cr);
  for (double y : chart.reference_y) {
    cairo_set_source_rgb(cr, 0.45, 0.45, 0.45);
    cairo_set_line_width(cr, 1.0);
    const double dash[] = {1.5, 3.0};
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
    const double dash[] = {6.0, 3.5};
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
  const TextStyle legend{.size = kFontSmall, .v = VAlign::middle};
  double widest = 0.0;
  for (const auto& s : chart.series) widest = std::max(widest, text_box(cr, s.name, legend).w);
  const double row = 1.3 * kFontSmall;
  const double lw = widest + 52.0, lh = row * chart.series.size() + 8.0;
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
  const std::vector<Rect> candidates{{plot.right() - lw - 8.0, plot.y + 8.0, lw, lh},
                                     {plot.right() - lw - 8.0, plot.bottom() - lh - 8.0, lw, lh},
                                     {plot.x + 8.0, plot.y + 8.0, lw, lh},
                                     {plot.x + 8.0, plot.bottom() - lh - 8.0, lw, lh},
                                     {plot.right() - lw - 8.0, plot.y + 0.5 * (plot.h - lh), lw, lh}};
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
    const double y = box.y + 4.0 + row * (k + 0.5);
    set_colour(cr, s.colour);
    cairo_set_line_width(cr, s.width);
    const double dash[] = {6.0, 3.5};
    cairo_set_dash(cr, dash, s.dashed ? 2 : 0, 0.0);
    cairo_move_to(cr, box.x + 6.0, y);
    cairo_line_to(cr, box.x + 40.0, y);
    cairo_stroke(cr);
    cairo_set_dash(cr, nullptr, 0, 0.0);
    draw_text(cr, s.name, box.x + 46.0, y, legend);
  }
  draw_title(cr, area.x + 10.0, area.y + 10.0, chart.title, chart.subtitle, kFontTitle, area.w - 20.0);
}

void write_line_chart(const std::filesystem::path& path, const LineChart& chart, int width, int height) {
  Canvas canvas(width, height);
  canvas.set_title(chart.title);
  draw_line_chart(canvas.cr(), {0.0, 0.0, static_cast<double>(width), static_cast<double>(height)}, chart);
  canvas.write(path);
}

}  // namespace trapdem::plot
