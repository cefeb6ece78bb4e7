#include "plot/comparison_figure.hpp"

#include <algorithm>
#include <cmath>

#include "plot/axes.hpp"
#include "plot/canvas.hpp"
#include "plot/contour_plot.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

namespace {

constexpr double mm = 1000.0;
const Rgb dem_colour{0.10, 0.25, 0.60};
const Rgb piv_colour{0.90, 0.45, 0.05};
const Rgb trapdoor_colour{0.80, 0.10, 0.10};

// Largest settlement (-w) of either field, m.
double largest_settlement(const ComparisonFigure& f) {
  double s = 0.0;
  for (const GridField* g : {&f.dem, &f.piv}) {
    for (double v : g->value) {
      if (std::isfinite(v)) s = std::max(s, -v);
    }
  }
  return s;
}

GridField settlement(GridField g) {
  for (double& v : g.value) v = -v;
  return g;
}

}  // namespace

void write_comparison_figure(const std::filesystem::path& path, const ComparisonFigure& fig, int width) {
  // Title block, then the legend (three rows), then the map.
  const double right = 16.0, left = 4.4 * kFontSmall, bottom = 3.5 * kFontSmall, row = 1.3 * kFontSmall;
  const double legend_top = 10.0 + title_height(fig.title, fig.subtitle, kFontTitle, width - 20.0) + 4.0;
  const double top = legend_top + 3.0 * row + 8.0;
  const double travel = std::max(0.0, fig.trapdoor_travel);
  const Range1 xr{fig.box_left * mm, fig.box_right * mm};
  const double zspan = std::max(fig.box_height, 1e-6);
  const Range1 zr{-(travel + 0.04 * zspan) * mm, (fig.box_height + 0.02 * zspan) * mm};
  const double plot_w = width - left - right;
  const double plot_h = std::min(1.2 * width, plot_w * zr.span() / xr.span());
  Canvas canvas(width, static_cast<int>(std::ceil(top + plot_h + bottom + 6.0)));
  canvas.set_title(fig.title);
  cairo_t* cr = canvas.cr();
  const Rect plot = fit_equal_aspect({left, top, plot_w, plot_h}, xr, zr);
  const PlotFrame f(plot, xr, zr);

  // Compared area, shaded cell by cell.
  cairo_save(cr);
  f.clip(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  cairo_set_source_rgb(cr, 0.90, 0.93, 0.97);
  const GridSpec& g = fig.dem.grid;
  const double h = g.spacing;
  for (std::size_t j = 0; j < g.nz; ++j) {
    for (std::size_t i = 0; i < g.nx; ++i) {
      if (!std::isfinite(fig.dem.at(i, j)) || !std::isfinite(fig.piv.at(i, j))) continue;
      const double x0 = f.px((g.x(i) - 0.5 * h) * mm), x1 = f.px((g.x(i) + 0.5 * h) * mm);
      const double y0 = f.py((g.z(j) + 0.5 * h) * mm), y1 = f.py((g.z(j) - 0.5 * h) * mm);
      cairo_rectangle(cr, std::floor(x0), std::floor(y0), std::ceil(x1) - std::floor(x0), std::ceil(y1) - std::floor(y0));
    }
  }
  cairo_fill(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);

  // Box outline: walls and base with the trapdoor opening; the trapdoor at its lowered position.
  const double hw = 0.5 * fig.trapdoor_width;
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
  cairo_set_line_width(cr, 3.0);
  cairo_move_to(cr, f.px(fig.box_left * mm) + 2, f.py(fig.box_height * mm));
  cairo_line_to(cr, f.px(fig.box_left * mm) + 2, f.py(0.0) + 2);
  cairo_line_to(cr, f.px(-hw * mm), f.py(0.0) + 2);
  cairo_move_to(cr, f.px(hw * mm), f.py(0.0) + 2);
  cairo_line_to(cr, f.px(fig.box_right * mm) - 2, f.py(0.0) + 2);
  cairo_line_to(cr, f.px(fig.box_right * mm) - 2, f.py(fig.box_height * mm));
  cairo_stroke(cr);
  cairo_set_line_width(cr, 1.2);
  const double wall_dash[] = {4.0, 3.0};
  cairo_set_dash(cr, wall_dash, 2, 0.0);
  cairo_move_to(cr, f.px(-hw * mm), f.py(0.0));
  cairo_line_to(cr, f.px(-hw * mm), plot.bottom());
  cairo_move_to(cr, f.px(hw * mm), f.py(0.0));
  cairo_line_to(cr, f.px(hw * mm), plot.bottom());
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  set_colour(cr, trapdoor_colour);
  cairo_set_line_width(cr, 4.0);
  cairo_move_to(cr, f.px(-hw * mm) + 2, f.py(-travel * mm) + 2.0);
  cairo_line_to(cr, f.px(hw * mm) - 2, f.py(-travel * mm) + 2.0);
  cairo_stroke(cr);
  cairo_restore(cr);

  // Settlement contours (downward positive) at the same nice levels for both.
  const std::vector<double> levels = contour_levels({}, 0.0, largest_settlement(fig));
  std::vector<double> levels_mm;
  for (double v : levels) levels_mm.push_back(v * mm);
  auto label = [&](double v) { return contour_label(v * mm, levels_mm); };
  ContourStyle dem_style;
  dem_style.colour = dem_colour;
  dem_style.line_width = 1.6;
  draw_contours(cr, f, settlement(fig.dem), levels, label, dem_style);
  ContourStyle piv_style;
  piv_style.colour = piv_colour;
  piv_style.line_width = 1.6;
  piv_style.min_label_length = 1e9;  // labels on the DEM lines only
  cairo_save(cr);
  const double dash[] = {6.0, 3.5};
  cairo_set_dash(cr, dash, 2, 0.0);
  draw_contours(cr, f, settlement(fig.piv), levels, label, piv_style);
  cairo_restore(cr);

  AxesStyle axes;
  axes.x_label = "x from the trapdoor centre (mm)";
  axes.y_label = "z (mm)";
  axes.font_size = kFontSmall;
  axes.max_x_ticks = std::max(3, static_cast<int>(plot.w / (3.2 * kFontSmall)));
  axes.max_y_ticks = std::max(3, static_cast<int>(plot.h / (2.2 * kFontSmall)));
  draw_axes(cr, f, axes);

  // Legend between the title and the map.
  const TextStyle ts{.size = kFontSmall, .v = VAlign::middle};
  const double lx = 10.0;
  auto entry = [&](double y, Rgb c, bool dashed, const std::string& text) {
    cairo_save(cr);
    set_colour(cr, c);
    cairo_set_line_width(cr, 1.6);
    if (dashed) cairo_set_dash(cr, dash, 2, 0.0);
    cairo_move_to(cr, lx, y);
    cairo_line_to(cr, lx + 36, y);
    cairo_stroke(cr);
    cairo_restore(cr);
    draw_text(cr, text, lx + 44, y, ts);
  };
  entry(legend_top + 0.5 * row, dem_colour, false, fig.dem_label + " settlement (mm, down +; labelled)");
  entry(legend_top + 1.5 * row, piv_colour, true, fig.piv_label + " settlement (mm), same levels");
  cairo_set_source_rgb(cr, 0.90, 0.93, 0.97);
  cairo_rectangle(cr, lx, legend_top + 2.1 * row, 36, 0.8 * row);
  cairo_fill(cr);
  draw_text(cr, "compared area", lx + 44, legend_top + 2.5 * row, ts);

  draw_title(cr, 10.0, 10.0, fig.title, fig.subtitle, kFontTitle, width - 20.0);
  canvas.write(path);
}

}  // namespace trapdem::plot
