#include "plot/specimen_figures.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <fmt/format.h>

#include "core/length_text.hpp"
#include "plot/colour_bar.hpp"
#include "plot/colour_map.hpp"
#include "analysis/field_smoothing.hpp"
#include "analysis/hole_fill.hpp"
#include "plot/canvas.hpp"

namespace trapdem::plot {

namespace {

constexpr double mm = 1000.0;
const Rgb trapdoor_colour{0.80, 0.10, 0.10};

// The total map shows gamma_max smoothed at the analysis's smoothing length (the field the bands
// are traced on) when that length is positive, else the unsmoothed triangles.
bool shows_smoothed(const AnalysisResult& r, StrainKind kind) {
  return kind == StrainKind::total && r.settings.bands.smoothing_diameters > 0.0 &&
         r.gamma_max_smoothed.size() == r.gamma_max.size();
}

const std::vector<double>& strain_values(const AnalysisResult& r, StrainKind kind) {
  if (kind == StrainKind::incremental) return r.gamma_max_incremental;
  return shows_smoothed(r, kind) ? r.gamma_max_smoothed : r.gamma_max;
}

std::string smoothing_text(const AnalysisResult& r) {
  return fmt::format("smoothed over a Gaussian of {:g} d = {}", r.settings.bands.smoothing_diameters,
                     format_mm(r.settings.bands.smoothing_diameters * r.mean_diameter));
}

// Data ranges (mm) for a spatial figure: the box width, from below the lowered trapdoor to just
// above the highest particle.
Range1 x_range_mm(const AnalysisResult& r) { return {0.0, r.geometry.box_width * mm}; }
Range1 z_range_mm(const AnalysisResult& r) {
  double top = 0.0;
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    top = std::max(top, r.points.position[k].z + r.radius[k]);
  }
  const double bottom = -(r.trapdoor_travel() + 0.5 * r.mean_diameter + 0.02 * top);
  return {bottom * mm, (top + 0.5 * r.mean_diameter) * mm};
}

// Base on both sides of the trapdoor (at z = 0) and the trapdoor at its current position (travel
// and box width in m).
void draw_base_and_trapdoor(cairo_t* cr, const PlotFrame& f, const TrapdoorGeometry& t, double travel,
                            double box_width) {
  const double z0 = f.py(0.0), zt = f.py(-travel * mm);
  cairo_save(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
  cairo_set_line_width(cr, 4.0);
  cairo_move_to(cr, f.px(0.0), z0 + 2.0);
  cairo_line_to(cr, f.px(t.left_edge() * mm), z0 + 2.0);
  cairo_move_to(cr, f.px(t.right_edge() * mm), z0 + 2.0);
  cairo_line_to(cr, f.px(box_width * mm), z0 + 2.0);
  cairo_stroke(cr);
  // cavity walls
  cairo_set_line_width(cr, 1.5);
  const double dash[] = {3.0, 2.5};
  cairo_set_dash(cr, dash, 2, 0.0);
  cairo_move_to(cr, f.px(t.left_edge() * mm), z0);
  cairo_line_to(cr, f.px(t.left_edge() * mm), f.pixels().bottom());
  cairo_move_to(cr, f.px(t.right_edge() * mm), z0);
  cairo_line_to(cr, f.px(t.right_edge() * mm), f.pixels().bottom());
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  set_colour(cr, trapdoor_colour);
  cairo_set_line_width(cr, 4.0);
  cairo_move_to(cr, f.px(t.left_edge() * mm) + 2, zt + 2.0);
  cairo_line_to(cr, f.px(t.right_edge() * mm) - 2, zt + 2.0);
  cairo_stroke(cr);
  cairo_restore(cr);
}

void draw_base_and_trapdoor(cairo_t* cr, const PlotFrame& f, const AnalysisResult& r) {
  draw_base_and_trapdoor(cr, f, r.geometry.trapdoor, r.trapdoor_travel(), r.geometry.box_width);
}

// The plot area for a box map in `space`, leaving `left` and `bottom` units for the axes.
PlotFrame map_frame(Rect space, const AnalysisResult& r, double left, double bottom) {
  const Range1 x = x_range_mm(r), z = z_range_mm(r);
  const Rect plot = fit_equal_aspect({space.x + left, space.y, space.w - left, space.h - bottom}, x, z);
  return PlotFrame(plot, x, z);
}

double map_height_for_width(const AnalysisResult& r, double width) {
  const Range1 x = x_range_mm(r), z = z_range_mm(r);
  return width * z.span() / x.span();
}

std::string short_displacement_text(const AnalysisResult& r) {
  return fmt::format("δ = {}, δ/B = {:.2f}", format_mm(r.trapdoor_travel()),
                     r.trapdoor_travel() / r.geometry.trapdoor.width);
}

std::string displacement_text(const AnalysisResult& r) {
  return fmt::format("trapdoor displacement δ = {} (δ/B = {:.2f})", format_mm(r.trapdoor_travel()),
                     r.trapdoor_travel() / r.geometry.trapdoor.width);
}

std::string view_text(const AnalysisResult& r) {
  if (r.settings.view == ViewKind::all) return fmt::format("all {} particles", r.id.size());
  return fmt::format("{} particles within {} of the glass", r.id.size(), format_mm(r.settings.front_depth));
}

// A band's trace: white halo, then a dashed line (bands magenta, their branches orange, thinner).
void stroke_trace(cairo_t* cr, const PlotFrame& f, const std::vector<BandTracePoint>& trace, bool branch) {
  if (trace.size() < 2) return;
  const double width = branch ? 1.3 : 1.8;
  const Rgb colour = branch ? Rgb{1.0, 0.55, 0.0} : Rgb{0.9, 0.1, 0.5};
  for (int pass = 0; pass < 2; ++pass) {
    cairo_set_line_width(cr, pass == 0 ? width + 1.5 : width);
    if (pass == 0) cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
    else set_colour(cr, colour);
    const double dash[] = {5.0, 3.0};
    cairo_set_dash(cr, dash, pass == 0 ? 0 : 2, 0.0);
    for (std::size_t k = 0; k < trace.size(); ++k) {
      const double x = f.px(trace[k].x * mm), y = f.py(trace[k].z * mm);
      if (k == 0) cairo_move_to(cr, x, y);
      else cairo_line_to(cr, x, y);
    }
    cairo_stroke(cr);
  }
}

void draw_band_traces(cairo_t* cr, const PlotFrame& f, const AnalysisResult& r) {
  cairo_save(cr);
  f.clip(cr);
  for (const ShearBand* band : {&r.bands.left, &r.bands.right}) {
    stroke_trace(cr, f, band->trace, false);
    for (const auto& branch : band->branches) stroke_trace(cr, f, branch.trace, true);
  }
  cairo_restore(cr);
}

void draw_band_traces(cairo_t* cr, const PlotFrame& f, const StoredStrainMap& m) {
  cairo_save(cr);
  f.clip(cr);
  for (const auto& trace : m.band_traces) stroke_trace(cr, f, trace, false);
  for (const auto& trace : m.branch_traces) stroke_trace(cr, f, trace, true);
  cairo_restore(cr);
}

void draw_specimen_axes(cairo_t* cr, const PlotFrame& f, double font_size, bool x_title = true) {
  AxesStyle axes;
  if (x_title) axes.x_label = "x (mm)";
  axes.y_label = "z (mm)";
  axes.font_size = font_size;
  axes.max_x_ticks = std::max(3, static_cast<int>(f.pixels().w / (3.2 * font_size)));
  axes.max_y_ticks = std::max(3, static_cast<int>(f.pixels().h / (2.2 * font_size)));
  draw_axes(cr, f, axes);
}

// Room for the axes left of and below a map, for tick numbers of `font_size`.
double left_margin(double font_size) { return 4.4 * font_size; }
double bottom_margin(double font_size) { return 3.5 * font_size; }
// Right of a map: the colour bar, its numbers and its label.
constexpr double kBarGap = 14.0, kBarWidth = 16.0, kRightMargin = 150.0;

void trace_triangle(cairo_t* cr, const PlotFrame& f, const AnalysisResult& r, const TriangleNodes& tri) {
  for (int c = 0; c < 3; ++c) {
    const Point2 p = r.points.position[tri[static_cast<std::size_t>(c)]];
    if (c == 0) cairo_move_to(cr, f.px(p.x * mm), f.py(p.z * mm));
    else cairo_line_to(cr, f.px(p.x * mm), f.py(p.z * mm));
  }
  cairo_close_path(cr);
}

// Fills each kept triangle at its reference position with its value's colour (`colour(value)`),
// and the triangles the filter dropped inside the specimen with their neighbours' mean
// (hole_fill.hpp), so that the map has no holes; the dropped triangles at the boundary stay
// light grey (empty space).
template <class Colour>
void fill_triangles(cairo_t* cr, const PlotFrame& f, const AnalysisResult& r, const std::vector<double>& values,
                    Colour colour) {
  cairo_save(cr);
  f.clip(cr);
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
  cairo_paint(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  const auto fill = [&](const TriangleNodes& tri, double value) {
    set_colour(cr, colour(value));
    trace_triangle(cr, f, r, tri);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.5);
    cairo_stroke(cr);  // closes hairline seams between neighbours
  };
  for (std::size_t t = 0; t < r.mesh.mesh.size(); ++t) fill(r.mesh.mesh.triangles[t], values[t]);
  const FilledHoles holes = fill_interior_holes(r.mesh, values);
  for (std::size_t t = 0; t < holes.triangles.size(); ++t) fill(holes.triangles.triangles[t], holes.values[t]);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  cairo_restore(cr);
  cairo_save(cr);
  f.clip(cr);
  draw_base_and_trapdoor(cr, f, r);
  cairo_restore(cr);
}

// Fills each finite node's cell (one grid spacing square, centred on the node) with its value's
// colour; the rest stays light grey (empty space), as around the triangles.
template <class Colour>
void fill_grid(cairo_t* cr, const PlotFrame& f, const StoredStrainMap& m, Colour colour) {
  cairo_save(cr);
  f.clip(cr);
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
  cairo_paint(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  const GridSpec& g = m.gamma_max.grid;
  const double half = 0.5 * g.spacing;
  for (std::size_t j = 0; j < g.nz; ++j)
    for (std::size_t i = 0; i < g.nx; ++i) {
      const double v = m.gamma_max.at(i, j);
      if (!std::isfinite(v)) continue;
      const double x0 = f.px((g.x(i) - half) * mm), x1 = f.px((g.x(i) + half) * mm);
      const double z0 = f.py((g.z(j) - half) * mm), z1 = f.py((g.z(j) + half) * mm);
      set_colour(cr, colour(v));
      cairo_rectangle(cr, std::min(x0, x1), std::min(z0, z1), std::fabs(x1 - x0) + 0.5, std::fabs(z1 - z0) + 0.5);
      cairo_fill(cr);  // the half unit of overlap closes hairline seams between cells
    }
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  draw_base_and_trapdoor(cr, f, m.trapdoor, m.travel, m.box_width);
  cairo_restore(cr);
}

// A panel map's extent and captions, whichever its source.
Range1 x_range_mm(const StrainPanelMap& m) {
  return m.analysis ? x_range_mm(*m.analysis) : Range1{0.0, m.stored->box_width * mm};
}
Range1 z_range_mm(const StrainPanelMap& m) {
  if (m.analysis) return z_range_mm(*m.analysis);
  const StoredStrainMap& s = *m.stored;
  const GridSpec& g = s.gamma_max.grid;
  double top = 0.0;  // m, the top of the highest covered cell
  for (std::size_t j = 0; j < g.nz; ++j)
    for (std::size_t i = 0; i < g.nx; ++i)
      if (std::isfinite(s.gamma_max.at(i, j))) top = std::max(top, g.z(j) + 0.5 * g.spacing);
  const double bottom = -(s.travel + 0.5 * s.mean_diameter + 0.02 * top);
  return {bottom * mm, (top + 0.5 * s.mean_diameter) * mm};
}
std::string short_displacement_text(const StrainPanelMap& m) {
  if (m.analysis) return short_displacement_text(*m.analysis);
  return fmt::format("δ = {}, δ/B = {:.2f}, stored grid", format_mm(m.stored->travel),
                     m.stored->travel / m.stored->trapdoor.width);
}
const std::string& map_name(const StrainPanelMap& m) { return m.analysis ? m.analysis->geometry.name : m.stored->name; }
// The panel's title says whether the maps are smoothed, and at what length: the first map's.
double shown_smoothing_diameters(const StrainPanelMap& m) {
  if (m.analysis)
    return shows_smoothed(*m.analysis, StrainKind::total) ? m.analysis->settings.bands.smoothing_diameters : 0.0;
  return m.stored->smoothing_diameters;
}

// For a map's caption: what the filter dropped and how the map shows it.
std::string dropped_triangles_text(const AnalysisResult& r, const std::vector<double>& values) {
  const std::size_t dropped = r.mesh.dropped_long_edge + r.mesh.dropped_sliver;
  if (dropped == 0) return "no triangle dropped";
  const FilledHoles holes = fill_interior_holes(r.mesh, values);
  return fmt::format("{} triangles dropped ({} long-edge, {} sliver): {} inside drawn with their neighbours' mean, {} at "
                     "the boundary left blank",
                     dropped, r.mesh.dropped_long_edge, r.mesh.dropped_sliver, holes.triangles.size(),
                     holes.left_empty);
}

// The page of a single-map figure: the title block on top (wrapped to the width), the map below
// it with its axes, the colour bar on the right; the map's height follows the specimen's aspect
// (at most 1.2 times the width).
struct MapPage {
  MapPage(const AnalysisResult& r, int width, const std::string& title, const std::string& subtitle)
      : top(10.0 + title_height(title, subtitle, kFontTitle, width - 20.0) + 8.0),
        plot_h(std::min(1.2 * width, map_height_for_width(r, width - left_margin(kFontSmall) - kRightMargin))),
        canvas(width, static_cast<int>(std::ceil(top + plot_h + bottom_margin(kFontSmall) + 6.0))),
        frame(map_frame({0.0, top, width - kRightMargin, plot_h + bottom_margin(kFontSmall)}, r, left_margin(kFontSmall),
                        bottom_margin(kFontSmall))) {
    canvas.set_title(title);
    draw_title(canvas.cr(), 10.0, 10.0, title, subtitle, kFontTitle, width - 20.0);
  }

  Rect bar(bool extend_high) const {
    const Rect& p = frame.pixels();
    const double gap = extend_high ? 16.0 : 0.0;  // room for the triangle
    return {p.right() + kBarGap, p.y + gap, kBarWidth, p.h - gap};
  }

  double top, plot_h;
  Canvas canvas;
  PlotFrame frame;
};

ColourBarStyle bar_style(std::string label, double tick_scale = 1.0, bool extend_high = false) {
  ColourBarStyle s;
  s.label = std::move(label);
  s.font_size = kFontSmall;
  s.max_ticks = 5;
  s.tick_scale = tick_scale;
  s.extend_high = extend_high;
  return s;
}

}  // namespace

double auto_strain_scale(const AnalysisResult& r, StrainKind kind) {
  return nice_ceiling(quantile(strain_values(r, kind), 0.95));
}

double auto_strain_scale(const StoredStrainMap& m) { return nice_ceiling(quantile(m.gamma_max.value, 0.95)); }

std::vector<double> shown_volumetric_strain(const AnalysisResult& r) {
  const double length = r.settings.bands.smoothing_diameters * r.mean_diameter;
  if (!(length > 0.0) || r.volumetric.size() != r.mesh.mesh.size()) return r.volumetric;
  return smooth_triangle_field(make_triangle_field(r.mesh.mesh, r.points.position, r.volumetric), length).value;
}

PlotFrame draw_strain_map(cairo_t* cr, Rect area, const AnalysisResult& r, StrainKind kind, double vmax,
                          double font_size) {
  const PlotFrame f = map_frame(area, r, left_margin(font_size), bottom_margin(font_size));
  const ColourMap map(ColourMapKind::viridis);
  const auto& values = strain_values(r, kind);
  fill_triangles(cr, f, r, values, [&](double v) { return map.of(v, 0.0, vmax); });
  if (kind == StrainKind::total) draw_band_traces(cr, f, r);
  draw_specimen_axes(cr, f, font_size);
  return f;
}

PlotFrame write_strain_map(const std::filesystem::path& path, const AnalysisResult& r, StrainKind kind, double vmax,
                           int width) {
  if (!(vmax > 0.0)) vmax = auto_strain_scale(r, kind);
  const std::string what = kind == StrainKind::total ? "maximum shear strain γmax (total)"
                                                     : "accumulated incremental maximum shear strain";
  const std::string smoothing = shows_smoothed(r, kind) ? "; " + smoothing_text(r) : std::string();
  const std::string bands = kind == StrainKind::total ? "; dashed: traced band centres (orange: branches)" : "";
  MapPage page(r, width, fmt::format("{}: {}", r.geometry.name, what),
               fmt::format("{}; strain from {}, on the reference positions{}; {}{}; {}", displacement_text(r),
                           format_mm(r.reference_displacement), smoothing, view_text(r), bands,
                           dropped_triangles_text(r, strain_values(r, kind))));
  cairo_t* cr = page.canvas.cr();
  const PlotFrame f =
      draw_strain_map(cr, {0.0, page.top, width - kRightMargin, page.plot_h + bottom_margin(kFontSmall)}, r, kind, vmax);
  draw_colour_bar(cr, page.bar(true), ColourMap(ColourMapKind::viridis), 0.0, vmax,
                  bar_style(kind == StrainKind::total ? "γmax (-)" : "Σ Δγmax (-)", 1.0, true));
  page.canvas.write(path);
  return f;
}

PlotFrame write_volumetric_strain_map(const std::filesystem::path& path, const AnalysisResult& r, double vmax,
                                      int width) {
  const std::vector<double> values = shown_volumetric_strain(r);
  if (!(vmax > 0.0)) {
    std::vector<double> magnitude;
    for (double v : values) magnitude.push_back(std::abs(v));
    vmax = nice_ceiling(quantile(magnitude, 0.95));
  }
  const bool smoothed = r.settings.bands.smoothing_diameters > 0.0;
  MapPage page(r, width, fmt::format("{}: volumetric strain εv (total)", r.geometry.name),
               fmt::format("{}; strain from {}, on the reference positions{}; {}; red: compression (εv > 0), blue: "
                           "dilation (εv < 0); {}",
                           displacement_text(r), format_mm(r.reference_displacement),
                           smoothed ? "; " + smoothing_text(r) : std::string(), view_text(r),
                           dropped_triangles_text(r, values)));
  cairo_t* cr = page.canvas.cr();
  const ColourMap map(ColourMapKind::diverging);
  fill_triangles(cr, page.frame, r, values, [&](double v) { return map.of(v, -vmax, vmax); });
  draw_specimen_axes(cr, page.frame, kFontSmall);
  draw_colour_bar(cr, page.bar(false), map, -vmax, vmax, bar_style("volumetric strain εv (-), compression +"));
  page.canvas.write(path);
  return page.frame;
}

namespace {

// Settlement (downward displacement, m) colour scale of the displacement maps: -travel..travel.
struct SettlementScale {
  double travel;
  ColourMap map{ColourMapKind::diverging};
  Rgb of(double settlement) const { return map.of(settlement, -travel, travel); }
};

void finish_settlement_map(MapPage& page, const SettlementScale& scale) {
  cairo_t* cr = page.canvas.cr();
  draw_specimen_axes(cr, page.frame, kFontSmall);
  draw_colour_bar(cr, page.bar(false), scale.map, -scale.travel, scale.travel,
                  bar_style("settlement −w (mm), downward +", mm));
}

}  // namespace

PlotFrame write_displacement_contours(const std::filesystem::path& path, const AnalysisResult& r,
                                      const ContourLevels& spec, int width) {
  const GridField& w = r.vertical_displacement;
  // Settlement s = -w (downward positive): the colour fill, the contour labels and the colour bar.
  GridField settlement = w;
  double lo = 0.0, hi = 0.0;
  for (double& v : settlement.value) {
    v = -v;
    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  const std::vector<double> levels = contour_levels(spec, lo, hi);
  std::string levels_text = "automatic levels";
  if (!spec.list.empty()) levels_text = "levels as given";
  else if (spec.step > 0.0) levels_text = fmt::format("levels every {}", format_mm(spec.step));
  MapPage page(r, width, fmt::format("{}: settlement contours (mm)", r.geometry.name),
               fmt::format("{}; settlement −w, downward positive, on the reference positions; {}; grid {}; {}",
                           displacement_text(r), levels_text, format_mm(r.settings.grid_spacing), view_text(r)));
  cairo_t* cr = page.canvas.cr();
  const PlotFrame& f = page.frame;
  const SettlementScale scale{r.trapdoor_travel()};
  cairo_save(cr);
  f.clip(cr);
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
  cairo_paint(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  const double h = w.grid.spacing;
  for (std::size_t j = 0; j < w.grid.nz; ++j) {
    for (std::size_t i = 0; i < w.grid.nx; ++i) {
      const double v = settlement.at(i, j);
      if (std::isnan(v)) continue;
      set_colour(cr, scale.of(v));
      const double x0 = f.px((w.grid.x(i) - 0.5 * h) * mm), x1 = f.px((w.grid.x(i) + 0.5 * h) * mm);
      const double y0 = f.py((w.grid.z(j) + 0.5 * h) * mm), y1 = f.py((w.grid.z(j) - 0.5 * h) * mm);
      cairo_rectangle(cr, x0, y0, x1 - x0 + 0.3, y1 - y0 + 0.3);
      cairo_fill(cr);
    }
  }
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  draw_base_and_trapdoor(cr, f, r);
  cairo_restore(cr);
  std::vector<double> levels_mm;
  for (double v : levels) levels_mm.push_back(v * mm);
  ContourStyle style;
  style.line_width = 1.2;
  draw_contours(cr, f, settlement, levels, [&](double v) { return contour_label(v * mm, levels_mm); }, style);
  finish_settlement_map(page, scale);
  page.canvas.write(path);
  return f;
}

PlotFrame write_particles_figure(const std::filesystem::path& path, const AnalysisResult& r, int width) {
  MapPage page(r, width, fmt::format("{}: particles coloured by settlement", r.geometry.name),
               fmt::format("{}; current positions, radius to scale; {}", displacement_text(r), view_text(r)));
  cairo_t* cr = page.canvas.cr();
  const PlotFrame& f = page.frame;
  const SettlementScale scale{r.trapdoor_travel()};
  cairo_save(cr);
  f.clip(cr);
  const double units_per_mm = f.scale_x();
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    const Point2 p = r.points.position[k] + r.points.displacement[k];
    cairo_new_sub_path(cr);
    cairo_arc(cr, f.px(p.x * mm), f.py(p.z * mm), r.radius[k] * mm * units_per_mm, 0.0, 2.0 * M_PI);
    set_colour(cr, scale.of(-r.points.displacement[k].z));
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0.2, 0.2, 0.2, 0.7);
    cairo_set_line_width(cr, 0.4);
    cairo_stroke(cr);
  }
  draw_base_and_trapdoor(cr, f, r);
  cairo_restore(cr);
  finish_settlement_map(page, scale);
  page.canvas.write(path);
  return f;
}

std::vector<PlotFrame> write_strain_panel_of_maps(const std::filesystem::path& path,
                                                  const std::vector<StrainPanelMap>& results,
                                                  const std::vector<std::string>& labels, double vmax) {
  std::vector<PlotFrame> frames;
  if (results.empty()) return frames;
  for (const StrainPanelMap& m : results)
    if ((m.analysis == nullptr) == (m.stored == nullptr))
      throw std::invalid_argument("write_strain_panel_of_maps: each map is an analysis or a stored map, not both or neither");
  if (!(vmax > 0.0)) {
    for (const StrainPanelMap& m : results)
      vmax = std::max(vmax, m.analysis ? auto_strain_scale(*m.analysis) : auto_strain_scale(*m.stored));
  }
  const std::size_t n = results.size();
  const std::size_t columns = n <= 4 ? 1 : 2;
  const std::size_t rows = (n + columns - 1) / columns;
  const double font = kFontSmall, left = left_margin(font), bottom = bottom_margin(font);
  const double cell_w = columns == 1 ? kFigureWidth - kRightMargin : 0.5 * (1.3 * kFigureWidth - kRightMargin);
  const double width = columns * cell_w + kRightMargin;
  // One length scale: the widest box fills its cell; one vertical range: the union of the runs'.
  double widest = 0.0, z_lo = 0.0, z_hi = 0.0;
  for (const StrainPanelMap& r : results) {
    widest = std::max(widest, x_range_mm(r).span());
    const Range1 z = z_range_mm(r);
    z_lo = std::min(z_lo, z.lo), z_hi = std::max(z_hi, z.hi);
  }
  const double units_per_mm = (cell_w - left - 8.0) / widest;
  const double plot_h = (z_hi - z_lo) * units_per_mm;
  // "(a) label" (wrapped to the cell: a long case label ran into the colour bar) and "δ = ..." above
  // each map.
  const TextStyle label_style{.size = kFontLabel, .bold = true, .h = HAlign::centre, .v = VAlign::bottom};
  const double label_line = 1.2 * kFontLabel;
  std::vector<std::vector<std::string>> label_lines;
  std::size_t most_lines = 1;
  for (std::size_t k = 0; k < n; ++k) {
    const std::string name = k < labels.size() && !labels[k].empty() ? labels[k] : map_name(results[k]);
    label_lines.push_back(wrap_text(fmt::format("({}) {}", static_cast<char>('a' + k % 26), name), label_style, cell_w - 8.0));
    most_lines = std::max(most_lines, label_lines.back().size());
  }
  const double label_h = 2.6 * font + (most_lines - 1) * label_line;
  // The x axis title under the last row only (every panel has the same x scale).
  const double cell_h = label_h + plot_h + bottom - 1.5 * font + 6.0;
  const double smoothing = shown_smoothing_diameters(results.front());
  const std::string title = fmt::format("Maximum shear strain γmax (total{}), one colour and length scale",
                                        smoothing > 0.0 ? fmt::format(", smoothed over {:g} d", smoothing) : std::string());
  const double top = 10.0 + title_height(title, "", kFontTitle, width - 20.0) + 4.0;
  Canvas canvas(static_cast<int>(std::ceil(width)), static_cast<int>(std::ceil(top + rows * cell_h + 1.5 * font)));
  canvas.set_title(title);
  cairo_t* cr = canvas.cr();
  draw_title(cr, 10.0, 10.0, title, "", kFontTitle, width - 20.0);
  for (std::size_t k = 0; k < n; ++k) {
    const StrainPanelMap& r = results[k];
    const double cell_x = (k % columns) * cell_w, cell_y = top + (k / columns) * cell_h;
    const Range1 x = x_range_mm(r), z{z_lo, z_hi};
    const PlotFrame f({cell_x + left, cell_y + label_h, x.span() * units_per_mm, plot_h}, x, z);
    const ColourMap map(ColourMapKind::viridis);
    const auto colour = [&](double v) { return map.of(v, 0.0, vmax); };
    if (r.analysis) {
      fill_triangles(cr, f, *r.analysis, strain_values(*r.analysis, StrainKind::total), colour);
      draw_band_traces(cr, f, *r.analysis);
    } else {
      fill_grid(cr, f, *r.stored, colour);
      draw_band_traces(cr, f, *r.stored);
    }
    draw_specimen_axes(cr, f, font, k / columns + 1 == rows || k + columns >= n);
    const double centre = f.pixels().x + 0.5 * f.pixels().w;
    // The label centred over the map where it fits, else kept inside the cell.
    for (std::size_t i = 0; i < label_lines[k].size(); ++i) {
      const double half = 0.5 * text_width(label_lines[k][i], label_style);
      const double lo = cell_x + 4.0 + half, hi = cell_x + cell_w - 4.0 - half;
      const double at = lo <= hi ? std::clamp(centre, lo, hi) : cell_x + 0.5 * cell_w;
      draw_text(cr, label_lines[k][i], at, cell_y + 1.15 * font + i * label_line, label_style);
    }
    draw_text(cr, short_displacement_text(r), centre, f.pixels().y - 4.0,
              TextStyle{.size = font, .colour = {0.3, 0.3, 0.3}, .h = HAlign::centre, .v = VAlign::bottom});
    frames.push_back(f);
  }
  const double bar_top = top + label_h + 16.0, bar_bottom = top + (rows - 1) * cell_h + label_h + plot_h;
  draw_colour_bar(cr, {width - kRightMargin + kBarGap, bar_top, kBarWidth, bar_bottom - bar_top},
                  ColourMap(ColourMapKind::viridis), 0.0, vmax, bar_style("γmax (-)", 1.0, true));
  canvas.write(path);
  return frames;
}

std::vector<PlotFrame> write_strain_panel(const std::filesystem::path& path,
                                          const std::vector<const AnalysisResult*>& results,
                                          const std::vector<std::string>& labels, double vmax) {
  std::vector<StrainPanelMap> maps;
  for (const AnalysisResult* r : results) maps.push_back({r, nullptr});
  return write_strain_panel_of_maps(path, maps, labels, vmax);
}

}  // namespace trapdem::plot
