#include "plot/piv_figures.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/grid_field.hpp"
#include "analysis/grid_interpolation.hpp"
#include "plot/colour_bar.hpp"
#include "plot/colour_map.hpp"
#include "plot/contour_plot.hpp"

namespace trapdem::plot {

namespace {

// The value of rank floor(q n) among the finite values (NaN if none).
double rank_quantile(std::vector<double> v, double q) {
  std::erase_if(v, [](double x) { return !std::isfinite(x); });
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

PhotoFigure photo_figure(const PivFigureData& d, const std::string& title, const std::string& subtitle) {
  return PhotoFigure(d.first_image.width, d.first_image.height, d.pixel_to_plot, title, subtitle);
}

ColourBarStyle bar_style(std::string label, bool extend_high = false) {
  ColourBarStyle cb;
  cb.label = std::move(label);
  cb.font_size = kFontSmall;
  cb.max_ticks = 5;
  cb.extend_high = extend_high;
  return cb;
}

void draw_arrow(cairo_t* cr, std::array<double, 2> a, std::array<double, 2> b, double head) {
  cairo_move_to(cr, a[0], a[1]);
  cairo_line_to(cr, b[0], b[1]);
  cairo_stroke(cr);
  const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
  if (len < 1e-9) return;
  const double ux = (b[0] - a[0]) / len, uy = (b[1] - a[1]) / len;
  const double hl = std::min(head, 0.5 * len);
  cairo_move_to(cr, b[0], b[1]);
  cairo_line_to(cr, b[0] - hl * ux + 0.5 * hl * uy, b[1] - hl * uy - 0.5 * hl * ux);
  cairo_line_to(cr, b[0] - hl * ux - 0.5 * hl * uy, b[1] - hl * uy + 0.5 * hl * ux);
  cairo_close_path(cr);
  cairo_fill(cr);
}

}  // namespace

PhotoPlacement write_piv_strain_figure(const std::filesystem::path& path, const PivFigureData& d, bool incremental) {
  const StrainTriangles& s = incremental ? d.incremental_strain : d.total_strain;
  const auto valid = std::count_if(d.subsets.begin(), d.subsets.end(),
                                   [](const SubsetView& v) { return v.mark == SubsetMark::valid; });
  const std::size_t n = d.image_number;
  PhotoFigure figure = photo_figure(
      d, fmt::format("{}: {} shear strain", d.title, incremental ? "incremental" : "total"),
      fmt::format("image {} to image {}, over image {}; {} of {} subsets valid; blank: no valid triangle",
                  incremental ? n - 1 : 1, n, n, valid, d.subsets.size()));
  cairo_t* cr = figure.cr();
  const PlotFrame& f = figure.frame();
  figure.draw_photograph(d.last_image, 0.0);
  const double vmax = nice_ceiling(rank_quantile(s.max_shear, 0.95));
  const ColourMap map(ColourMapKind::viridis);
  cairo_save(cr);
  f.clip(cr);
  // Each soil element where it is in the image shown (incremental: the positions are those of the
  // image before, plus the increment, so the triangles end there too).
  for (std::size_t t = 0; t < s.mesh.size(); ++t) {
    const auto& tri = s.mesh.triangles[t];
    for (int c = 0; c < 3; ++c) {
      const Point2 p = s.position[tri[c]] + s.displacement[tri[c]];
      if (c == 0) cairo_move_to(cr, f.px(p.x), f.py(p.z));
      else cairo_line_to(cr, f.px(p.x), f.py(p.z));
    }
    cairo_close_path(cr);
    set_colour(cr, map.of(s.max_shear[t], 0.0, vmax), 0.72);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.3);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
  figure.draw_axes(d.unit);
  const Rect bar = figure.colour_bar_rect();
  draw_colour_bar(cr, {bar.x, bar.y + 12.0, bar.w, bar.h - 12.0}, map, 0.0, vmax,
                  bar_style(incremental ? "incremental γmax (-)" : "max shear strain γmax (-)", true));
  figure.write(path);
  return figure.placement();
}

PhotoPlacement write_piv_vertical_displacement_figure(const std::filesystem::path& path, const PivFigureData& d,
                                           const ContourLevels& spec) {
  const StrainTriangles& s = d.total_strain;
  std::string levels_text = "automatic levels";
  if (!spec.list.empty()) levels_text = "levels as given";
  else if (spec.step > 0.0) levels_text = fmt::format("levels every {:g} {}", spec.step, d.unit);
  PhotoFigure figure = photo_figure(
      d, fmt::format("{}: settlement", d.title),
      fmt::format("image 1 to image {}, at the subsets' positions in image 1 (shown); settlement = downward "
                  "displacement, heave negative; {}",
                  d.image_number, levels_text));
  cairo_t* cr = figure.cr();
  const PlotFrame& f = figure.frame();
  figure.draw_photograph(d.first_image, 0.55);
  const ColourMap map(ColourMapKind::diverging);
  // Settlement (-z displacement, plot units): the fill, the contour labels and the colour bar.
  double top = 0.0, lo = 0.0, hi = 0.0;
  std::vector<double> settlement;
  for (const auto& u : s.displacement) {
    settlement.push_back(-u.z);
    top = std::max(top, std::abs(u.z));
    lo = std::min(lo, -u.z), hi = std::max(hi, -u.z);
  }
  top = nice_ceiling(top);
  if (!s.mesh.triangles.empty()) {
    // Grid spacing: half a subset step in plot units.
    const PixelToPlot& m = d.pixel_to_plot;
    const double plot_per_px = std::sqrt(std::abs(m[0] * m[4] - m[1] * m[3]));
    const double spacing = 0.5 * d.grid_step * plot_per_px;
    const GridSpec grid = grid_covering(s.position, spacing);
    const GridField field = interpolate_nodal_field(s.mesh, s.position, settlement, grid);
    cairo_save(cr);
    f.clip(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (std::size_t j = 0; j < grid.nz; ++j) {
      for (std::size_t i = 0; i < grid.nx; ++i) {
        const double v = field.at(i, j);
        if (!std::isfinite(v)) continue;
        const double x0 = f.px(grid.x(i) - 0.5 * spacing), x1 = f.px(grid.x(i) + 0.5 * spacing);
        const double y0 = f.py(grid.z(j) + 0.5 * spacing), y1 = f.py(grid.z(j) - 0.5 * spacing);
        set_colour(cr, map.of(v, -top, top), 0.75);
        cairo_rectangle(cr, x0, y0, x1 - x0 + 0.3, y1 - y0 + 0.3);
        cairo_fill(cr);
      }
    }
    cairo_restore(cr);
    const std::vector<double> levels = contour_levels(spec, lo, hi, 10);
    ContourStyle style;
    style.coordinate_scale = 1.0;
    style.line_width = 1.2;
    cairo_save(cr);
    f.clip(cr);
    draw_contours(cr, f, field, levels, [&](double v) { return contour_label(v, levels); }, style);
    cairo_restore(cr);
  }
  figure.draw_axes(d.unit);
  draw_colour_bar(cr, figure.colour_bar_rect(), map, -top, top,
                  bar_style(fmt::format("settlement ({}), down +", d.unit)));
  figure.write(path);
  return figure.placement();
}

PhotoPlacement write_piv_vectors_figure(const std::filesystem::path& path, const PivFigureData& d) {
  // Arrows at least 10 units apart. The frame's scale does not depend on the title block (the canvas
  // grows with it), so a figure without titles measures it.
  const double dev_per_px = photo_figure(d, "", "").device_per_pixel();
  const int stride = std::max(1, static_cast<int>(std::ceil(10.0 / (d.grid_step * dev_per_px))));
  std::vector<double> lengths;
  for (const auto& m : d.subsets) {
    if (m.mark == SubsetMark::valid) lengths.push_back(std::hypot(m.u, m.v));
  }
  const double typical = rank_quantile(lengths, 0.95);
  const double spacing_dev = stride * d.grid_step * dev_per_px;
  const double magnify = typical > 0.0 ? 1.6 * spacing_dev / (typical * dev_per_px) : 1.0;
  PhotoFigure figure = photo_figure(d, fmt::format("{}: displacement vectors", d.title),
                                    fmt::format("image 1 to image {}, drawn {:.3g} times their length (95th "
                                                "percentile {:.3g} px); every {} subset(s)",
                                                d.image_number, magnify, typical, stride));
  cairo_t* cr = figure.cr();
  figure.draw_photograph(d.first_image, 0.35);
  cairo_save(cr);
  figure.frame().clip(cr);
  cairo_set_line_width(cr, 1.0);
  cairo_set_source_rgb(cr, 0.80, 0.05, 0.05);
  for (const auto& m : d.subsets) {
    if (m.column % stride || m.row % stride || m.mark != SubsetMark::valid) continue;
    draw_arrow(cr, figure.device_of_pixel(m.x, m.y), figure.device_of_pixel(m.x + magnify * m.u, m.y + magnify * m.v),
               5.0);
  }
  cairo_restore(cr);
  figure.draw_axes(d.unit);
  figure.write(path);
  return figure.placement();
}

PhotoPlacement write_piv_quality_figure(const std::filesystem::path& path, const PivFigureData& d) {
  std::size_t flagged = 0, poor = 0, poor_lost = 0;
  for (const auto& m : d.subsets) {
    const bool no_texture = m.mark == SubsetMark::poor_texture || m.mark == SubsetMark::poor_texture_lost;
    poor += no_texture;
    poor_lost += m.mark == SubsetMark::poor_texture_lost;
    flagged += m.mark == SubsetMark::flagged;
  }
  PhotoFigure figure =
      photo_figure(d, fmt::format("{}: correlation quality, image {}", d.title, d.image_number),
                   fmt::format("ZNCC per subset; grey: too little texture in image 1 ({}; {} of them lost since); "
                               "red x: other flagged (low correlation, not converged, left image, lost: {})",
                               poor, poor_lost, flagged));
  cairo_t* cr = figure.cr();
  figure.draw_photograph(d.first_image, 0.0);
  const ColourMap map(ColourMapKind::viridis);
  const double lo = 0.6, hi = 1.0;
  const double half = 0.5 * d.grid_step;
  cairo_save(cr);
  figure.frame().clip(cr);
  for (const auto& m : d.subsets) {
    const auto [x0, y0] = figure.device_of_pixel(m.x - half, m.y - half);
    const auto [x1, y1] = figure.device_of_pixel(m.x + half, m.y + half);
    const double l = std::min(x0, x1), t = std::min(y0, y1), w = std::abs(x1 - x0), h = std::abs(y1 - y0);
    if (m.mark == SubsetMark::poor_texture || m.mark == SubsetMark::poor_texture_lost) {
      cairo_set_source_rgba(cr, 0.55, 0.55, 0.55, 0.75);
      cairo_rectangle(cr, l, t, w, h);
      cairo_fill(cr);
      continue;
    }
    if (std::isfinite(m.zncc)) {
      set_colour(cr, map.of(m.zncc, lo, hi), 0.8);
      cairo_rectangle(cr, l, t, w, h);
      cairo_fill(cr);
    }
    if (m.mark == SubsetMark::flagged) {
      const double cx = l + 0.5 * w, cy = t + 0.5 * h, a = std::max(2.0, 0.35 * std::min(w, h));
      cairo_set_source_rgb(cr, 0.9, 0.0, 0.0);
      cairo_set_line_width(cr, 1.0);
      cairo_move_to(cr, cx - a, cy - a);
      cairo_line_to(cr, cx + a, cy + a);
      cairo_move_to(cr, cx - a, cy + a);
      cairo_line_to(cr, cx + a, cy - a);
      cairo_stroke(cr);
    }
  }
  cairo_restore(cr);
  figure.draw_axes(d.unit);
  draw_colour_bar(cr, figure.colour_bar_rect(), map, lo, hi, bar_style("ZNCC (-)"));
  figure.write(path);
  return figure.placement();
}

}  // namespace trapdem::plot
