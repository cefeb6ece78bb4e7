#include "plot/colour_bar.hpp"

#include <algorithm>

#include "plot/axes.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

void draw_colour_bar(cairo_t* cr, Rect bar, const ColourMap& map, double lo, double hi, const ColourBarStyle& style) {
  cairo_save(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  const int rows = std::max(1, static_cast<int>(bar.h));
  for (int k = 0; k < rows; ++k) {
    const double t = (k + 0.5) / rows;
    set_colour(cr, map.at(t));
    cairo_rectangle(cr, bar.x, bar.bottom() - (k + 1) * bar.h / rows, bar.w, bar.h / rows + 0.5);
    cairo_fill(cr);
  }
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  if (style.extend_high) {
    set_colour(cr, map.at(1.0));
    cairo_move_to(cr, bar.x, bar.y);
    cairo_line_to(cr, bar.x + 0.5 * bar.w, bar.y - 0.8 * bar.w);
    cairo_line_to(cr, bar.right(), bar.y);
    cairo_close_path(cr);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);
  }
  cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
  cairo_set_line_width(cr, 1.0);
  cairo_rectangle(cr, bar.x, bar.y, bar.w, bar.h);
  cairo_stroke(cr);
  const double slo = lo * style.tick_scale, shi = hi * style.tick_scale;
  const auto ticks = nice_ticks(slo, shi, style.max_ticks);
  const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : 1.0;
  TextStyle label{.size = style.font_size, .h = HAlign::left, .v = VAlign::middle};
  double widest = 0.0;
  for (double v : ticks) {
    const double y = bar.bottom() - (v - slo) / (shi - slo) * bar.h;
    cairo_move_to(cr, bar.right(), y);
    cairo_line_to(cr, bar.right() + 5.0, y);
    cairo_stroke(cr);
    widest = std::max(widest, draw_text(cr, format_tick(v, step), bar.right() + 8.0, y, label).w);
  }
  if (!style.label.empty()) {
    // Along the bar, on as many lines as its length needs.
    TextStyle title{.size = style.font_size, .angle_deg = 90.0, .h = HAlign::centre, .v = VAlign::top};
    double x = bar.right() + 14.0 + widest;
    for (const std::string& line : wrap_text(cr, style.label, title, std::max(bar.h, 4.0 * style.font_size))) {
      draw_text(cr, line, x, bar.y + 0.5 * bar.h, title);
      x += 1.15 * style.font_size;
    }
  }
  cairo_restore(cr);
}

}  // namespace trapdem::plot
