#include "plot/error_surface.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "plot/canvas.hpp"
#include "plot/colour_bar.hpp"
#include "plot/colour_map.hpp"
#include "plot/line_chart.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

namespace {

void write_one_key(const std::filesystem::path& path, const ErrorSurface& s) {
  LineChart chart;
  chart.title = s.title;
  chart.subtitle = s.subtitle;
  chart.x_label = s.x_key;
  chart.y_label = s.error_label;
  LineSeries series;
  series.name = "error";
  series.colour = series_colour(0);
  for (std::size_t k = 0; k < s.x_values.size(); ++k) {
    if (!std::isfinite(s.error[k])) continue;
    series.x.push_back(std::stod(s.x_values[k]));
    series.y.push_back(s.error[k] * s.error_scale);
  }
  chart.series = {series};
  write_line_chart(path, chart);
}

}  // namespace

void write_error_surface(const std::filesystem::path& path, const ErrorSurface& s) {
  const std::size_t nx = s.x_values.size(), ny = s.y_key.empty() ? 1 : s.y_values.size();
  if (nx == 0 || s.error.size() != nx * ny) throw std::invalid_argument("error surface: grid and errors do not match");
  if (s.y_key.empty()) {
    write_one_key(path, s);
    return;
  }
  double lo = INFINITY, hi = -INFINITY;
  std::size_t best = s.error.size();
  for (std::size_t k = 0; k < s.error.size(); ++k) {
    if (!std::isfinite(s.error[k])) continue;
    lo = std::min(lo, s.error[k]);
    hi = std::max(hi, s.error[k]);
    if (best == s.error.size() || s.error[k] < s.error[best]) best = k;
  }
  if (!(hi > lo)) hi = lo + 1e-12;
  // Cells share kFigureWidth less the margins (at least 3.5 numbers wide each).
  const double left = 6.0 * kFontSmall, bottom = 4.2 * kFontSmall, right = 7.0 * kFontSmall;
  const double cell_w = std::max((kFigureWidth - left - right) / nx, 3.5 * kFontSmall);
  // Tall enough for the y key written along the grid (it ran into the title above a two-row grid).
  const TextStyle y_title{.size = kFontLabel, .angle_deg = 90.0, .h = HAlign::centre, .v = VAlign::top};
  const double cell_h = std::max(std::clamp(300.0 / ny, 2.2 * kFontSmall, 80.0), (text_width(s.y_key, y_title) + 20.0) / ny);
  const int width = static_cast<int>(std::ceil(left + nx * cell_w + right));
  const double top = 10.0 + title_height(s.title, s.subtitle, kFontTitle, width - 20.0) + 8.0;
  const int height = static_cast<int>(std::ceil(top + ny * cell_h + bottom));
  Canvas canvas(width, height);
  canvas.set_title(s.title);
  cairo_t* cr = canvas.cr();
  draw_title(cr, 10.0, 10.0, s.title, s.subtitle, kFontTitle, width - 20.0);
  const ColourMap map(ColourMapKind::viridis);
  for (std::size_t iy = 0; iy < ny; ++iy) {
    for (std::size_t ix = 0; ix < nx; ++ix) {
      const double e = s.error[iy * nx + ix];
      // Larger y values on top, as on any plot.
      const Rect cell{left + ix * cell_w, top + (ny - 1 - iy) * cell_h, cell_w, cell_h};
      set_colour(cr, std::isfinite(e) ? map.of(e, lo, hi) : Rgb{0.85, 0.85, 0.85});
      cairo_rectangle(cr, cell.x, cell.y, cell.w, cell.h);
      cairo_fill(cr);
      const bool dark = std::isfinite(e) && (e - lo) / (hi - lo) < 0.55;
      draw_text(cr, std::isfinite(e) ? fmt::format("{:.3g}", e * s.error_scale) : "—", cell.x + 0.5 * cell.w,
                cell.y + 0.5 * cell.h,
                TextStyle{.size = kFontSmall, .bold = iy * nx + ix == best,
                          .colour = dark ? Rgb{1, 1, 1} : Rgb{0.1, 0.1, 0.1}, .h = HAlign::centre, .v = VAlign::middle});
    }
  }
  if (best < s.error.size()) {
    const std::size_t bx = best % nx, by = best / nx;
    set_colour(cr, Rgb{0.85, 0.1, 0.1});
    cairo_set_line_width(cr, 3.0);
    cairo_rectangle(cr, left + bx * cell_w + 2.0, top + (ny - 1 - by) * cell_h + 2.0, cell_w - 4.0, cell_h - 4.0);
    cairo_stroke(cr);
  }
  const TextStyle tick{.size = kFontSmall, .h = HAlign::centre, .v = VAlign::top};
  for (std::size_t ix = 0; ix < nx; ++ix) draw_text(cr, s.x_values[ix], left + (ix + 0.5) * cell_w, top + ny * cell_h + 8.0, tick);
  for (std::size_t iy = 0; iy < ny; ++iy)
    draw_text(cr, s.y_values[iy], left - 10.0, top + (ny - 1 - iy + 0.5) * cell_h,
              TextStyle{.size = kFontSmall, .h = HAlign::right, .v = VAlign::middle});
  draw_text(cr, s.x_key, left + 0.5 * nx * cell_w, top + ny * cell_h + 1.8 * kFontSmall,
            TextStyle{.size = kFontLabel, .h = HAlign::centre, .v = VAlign::top});
  draw_text(cr, s.y_key, 8.0, top + 0.5 * ny * cell_h, y_title);
  ColourBarStyle bar{.label = s.error_label, .font_size = kFontSmall, .max_ticks = 5, .tick_scale = s.error_scale};
  draw_colour_bar(cr, {left + nx * cell_w + 14.0, top, 16.0, ny * cell_h}, map, lo, hi, bar);
  canvas.write(path);
}

}  // namespace trapdem::plot
