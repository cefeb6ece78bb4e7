#include "plot/contour_plot.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"

#include "plot/marching_squares.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

std::vector<double> contour_levels(const ContourLevels& spec, double lo, double hi, int automatic_count) {
  if (!spec.list.empty()) {
    std::vector<double> levels = spec.list;
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    return levels;
  }
  std::vector<double> levels;
  if (!(hi > lo)) return levels;
  const double step = spec.step > 0.0 ? spec.step : nice_step(hi - lo, automatic_count);
  if ((hi - lo) / step > 1000.0) {
    throw InputError(fmt::format("contour step {:g}: more than 1000 levels over the field's range {:g} to {:g}", step,
                                 lo, hi));
  }
  for (double k = std::floor(lo / step); k * step < hi; k += 1.0) {
    const double v = k * step;
    if (v > lo && std::abs(v) > 1e-9 * step) levels.push_back(v);
  }
  return levels;
}

std::string contour_label(double level, const std::vector<double>& levels) {
  // Four significant digits tell 1-2-5 levels and user lists apart and drop round-off (0.30000000004).
  const double step = levels.size() > 1 ? std::abs(levels[1] - levels[0]) : 1.0;
  if (std::abs(level) < 1e-9 * step) return "0";
  return fmt::format("{:.4g}", level);
}

int draw_contours(cairo_t* cr, const PlotFrame& frame, const GridField& field, const std::vector<double>& levels,
                  const std::function<std::string(double)>& label, const ContourStyle& style) {
  struct Pending {
    std::vector<std::pair<double, double>> pixels;
    double level;
  };
  std::vector<Pending> lines;
  for (double level : levels) {
    for (const ContourLine& line : contour_lines(field, level)) {
      Pending p{{}, level};
      for (const Point2& q : line.points) {
        p.pixels.emplace_back(frame.px(q.x * style.coordinate_scale), frame.py(q.z * style.coordinate_scale));
      }
      lines.push_back(std::move(p));
    }
  }
  cairo_save(cr);
  frame.clip(cr);
  set_colour(cr, style.colour);
  cairo_set_line_width(cr, style.line_width);
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  for (const auto& l : lines) {
    for (std::size_t k = 0; k < l.pixels.size(); ++k) {
      if (k == 0) cairo_move_to(cr, l.pixels[k].first, l.pixels[k].second);
      else cairo_line_to(cr, l.pixels[k].first, l.pixels[k].second);
    }
    cairo_stroke(cr);
  }
  // Labels: at 50 %, then 30 % or 70 % of the line's length, wherever the box is free.
  std::vector<Rect> placed;
  int count = 0;
  TextStyle ts{.size = style.font_size, .colour = style.colour};
  for (const auto& l : lines) {
    std::vector<double> s{0.0};
    for (std::size_t k = 1; k < l.pixels.size(); ++k) {
      s.push_back(s.back() + std::hypot(l.pixels[k].first - l.pixels[k - 1].first,
                                        l.pixels[k].second - l.pixels[k - 1].second));
    }
    if (s.back() < style.min_label_length) continue;
    const std::string text = label(l.level);
    for (double f : {0.5, 0.3, 0.7, 0.15, 0.85}) {
      const double target = f * s.back();
      std::size_t k = 1;
      while (k + 1 < s.size() && s[k] < target) ++k;
      const double t = s[k] > s[k - 1] ? (target - s[k - 1]) / (s[k] - s[k - 1]) : 0.0;
      const double x = l.pixels[k - 1].first + t * (l.pixels[k].first - l.pixels[k - 1].first);
      const double y = l.pixels[k - 1].second + t * (l.pixels[k].second - l.pixels[k - 1].second);
      TextStyle c = ts;
      c.h = HAlign::centre;
      c.v = VAlign::middle;
      Rect box = text_box(cr, text, c, x, y);
      box = {box.x - 3, box.y - 2, box.w + 6, box.h + 4};
      const Rect& fr = frame.pixels();
      if (box.x < fr.x || box.right() > fr.right() || box.y < fr.y || box.bottom() > fr.bottom()) continue;
      bool free = true;
      for (const Rect& r : placed) free = free && !r.overlaps(box);
      if (!free) continue;
      draw_text_on_box(cr, text, x, y, ts, {1.0, 1.0, 1.0}, 2.0);
      placed.push_back(box);
      ++count;
      break;
    }
  }
  cairo_restore(cr);
  return count;
}

}  // namespace trapdem::plot
