#include "plot/specimen_figures.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/length_text.hpp"
#include "plot/canvas.hpp"
#include "plot/colour_bar.hpp"
#include "plot/colour_map.hpp"
#include "plot/contour_plot.hpp"
#include "plot/text.hpp"

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

// Base on both sides of the trapdoor (at z = 0) and the trapdoor at its current position.
void draw_base_and_trapdoor(cairo_t* cr, const PlotFrame& f, const AnalysisResult& r) {
  const TrapdoorGeometry& t = r.geometry.trapdoor;
  const double z0 = f.py(0.0), zt = f.py(-r.trapdoor_travel() * mm);
  cairo_save(cr);
  cairo_set_line_cap(cr, CAIRO_LINE_CAP_BUTT);
  cairo_set_source_rgb(cr, 0.25, 0.25, 0.25);
  cairo_set_line_width(cr, 5.0);
  cairo_move_to(cr, f.px(0.0), z0 + 2.5);
  cairo_line_to(cr, f.px(t.left_edge() * mm), z0 + 2.5);
  cairo_move_to(cr, f.px(t.right_edge() * mm), z0 + 2.5);
  cairo_line_to(cr, f.px(r.geometry.box_width * mm), z0 + 2.5);
  cairo_stroke(cr);
  // cavity walls
  cairo_set_line_width(cr, 1.5);
  const double dash[] = {4.0, 3.0};
  cairo_set_dash(cr, dash, 2, 0.0);
  cairo_move_to(cr, f.px(t.left_edge() * mm), z0);
  cairo_line_to(cr, f.px(t.left_edge() * mm), f.pixels().bottom());
  cairo_move_to(cr, f.px(t.right_edge() * mm), z0);
  cairo_line_to(cr, f.px(t.right_edge() * mm), f.pixels().bottom());
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
  set_colour(cr, trapdoor_colour);
  cairo_set_line_width(cr, 5.0);
  cairo_move_to(cr, f.px(t.left_edge() * mm) + 2, zt + 2.5);
  cairo_line_to(cr, f.px(t.right_edge() * mm) - 2, zt + 2.5);
  cairo_stroke(cr);
  cairo_restore(cr);
}

// The plot area for a box map in `space`, leaving `left` and `bottom` pixels for the axes.
PlotFrame map_frame(Rect space, const AnalysisResult& r, double left, double bottom) {
  const Range1 x = x_range_mm(r), z = z_range_mm(r);
  const Rect plot = fit_equal_aspect({space.x + left, space.y, space.w - left, space.h - bottom}, x, z);
  return PlotFrame(plot, x, z);
}

double map_height_for_width(const AnalysisResult& r, double width) {
  const Range1 x = x_range_mm(r), z = z_range_mm(r);
  return width * z.span() / x.span();
}

std::string displacement_text(const AnalysisResult& r) {
  return fmt::format("trapdoor displacement δ = {} (δ/B = {:.2f})", format_mm(r.trapdoor_travel()),
                     r.trapdoor_travel() / r.geometry.trapdoor.width);
}

std::string view_text(const AnalysisResult& r) {
  if (r.settings.view == ViewKind::all) return fmt::format("all {} particles", r.id.size());
  return fmt::format("{} particles within {} of the glass", r.id.size(), format_mm(r.settings.front_depth));
}

void draw_band_traces(cairo_t* cr, const PlotFrame& f, const AnalysisResult& r) {
  cairo_save(cr);
  f.clip(cr);
  // A band's trace: white halo, then a dashed line (bands magenta, their branches orange, thinner).
  const auto stroke_trace = [&](const std::vector<BandTracePoint>& trace, double width, Rgb colour) {
    if (trace.size() < 2) return;
    for (int pass = 0; pass < 2; ++pass) {
      cairo_set_line_width(cr, pass == 0 ? width + 2.0 : width);
      if (pass == 0) cairo_set_source_rgba(cr, 1, 1, 1, 0.8);
      else set_colour(cr, colour);
      const double dash[] = {7.0, 4.0};
      cairo_set_dash(cr, dash, pass == 0 ? 0 : 2, 0.0);
      for (std::size_t k = 0; k < trace.size(); ++k) {
        const double x = f.px(trace[k].x * mm), y = f.py(trace[k].z * mm);
        if (k == 0) cairo_move_to(cr, x, y);
        else cairo_line_to(cr, x, y);
      }
      cairo_stroke(cr);
    }
  };
  for (const ShearBand* band : {&r.bands.left, &r.bands.right}) {
    stroke_trace(band->trace, 2.0, {0.9, 0.1, 0.5});
    for (const auto& branch : band->branches) stroke_trace(branch.trace, 1.5, {1.0, 0.55, 0.0});
  }
  cairo_restore(cr);
}

void draw_specimen_axes(cairo_t* cr, const PlotFrame& f, double font_size) {
  AxesStyle axes;
  axes.x_label = "x (mm)";
  axes.y_label = "z (mm)";
  axes.font_size = font_size;
  axes.max_x_ticks = std::max(3, static_cast<int>(f.pixels().w / (5.5 * font_size)));
  axes.max_y_ticks = std::max(3, static_cast<int>(f.pixels().h / (3.0 * font_size)));
  draw_axes(cr, f, axes);
}

constexpr double left_margin = 95.0, bottom_margin = 80.0;

}  // namespace

double auto_strain_scale(const AnalysisResult& r, StrainKind kind) {
  return nice_ceiling(quantile(strain_values(r, kind), 0.95));
}

PlotFrame draw_strain_map(cairo_t* cr, Rect area, const AnalysisResult& r, StrainKind kind, double vmax,
                          double font_size) {
  const PlotFrame f = map_frame(area, r, left_margin * font_size / 16.0, bottom_margin * font_size / 16.0);
  const ColourMap map(ColourMapKind::viridis);
  const auto& values = strain_values(r, kind);
  cairo_save(cr);
  f.clip(cr);
  // Specimen background: empty space light grey, so dropped triangles read as gaps.
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
  cairo_paint(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  for (std::size_t t = 0; t < r.mesh.mesh.size(); ++t) {
    const auto& tri = r.mesh.mesh.triangles[t];
    set_colour(cr, map.of(values[t], 0.0, vmax));
    for (int c = 0; c < 3; ++c) {
      const Point2 p = r.points.position[tri[static_cast<std::size_t>(c)]];
      if (c == 0) cairo_move_to(cr, f.px(p.x * mm), f.py(p.z * mm));
      else cairo_line_to(cr, f.px(p.x * mm), f.py(p.z * mm));
    }
    cairo_close_path(cr);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 1.0);
    cairo_stroke(cr);  // closes hairline seams between neighbours
  }
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  cairo_restore(cr);
  cairo_save(cr);
  f.clip(cr);
  draw_base_and_trapdoor(cr, f, r);
  cairo_restore(cr);
  if (kind == StrainKind::total) draw_band_traces(cr, f, r);
  draw_specimen_axes(cr, f, font_size);
  return f;
}

namespace {

// The page of a single-map figure: a title band on top, the colour bar on the right, the map's
// height following the specimen's aspect (at most 900 px).
struct MapLayout {
  int height;  // px, of the whole figure
  Rect area;   // where the framed map goes
};

MapLayout map_layout(const AnalysisResult& r, int width) {
  const double top = 110.0, right = 175.0;
  const double plot_h = std::min(900.0, map_height_for_width(r, width - left_margin - right));
  return {static_cast<int>(top + plot_h + bottom_margin + 10.0), Rect{0.0, top, width - right, plot_h + bottom_margin}};
}

// A map of the box coloured by vertical displacement (diverging, -travel to +travel): its canvas and
// frame; `finish` adds the axes, the title and the colour bar and writes the PNG.
struct DisplacementMap {
  DisplacementMap(const AnalysisResult& r, int width)
      : layout(map_layout(r, width)),
        canvas(width, layout.height),
        frame(map_frame(layout.area, r, left_margin, bottom_margin)),
        travel(r.trapdoor_travel()) {}

  void finish(const std::filesystem::path& path, const std::string& title, const std::string& subtitle) const {
    cairo_t* cr = canvas.cr();
    draw_specimen_axes(cr, frame, 16.0);
    draw_title(cr, frame.pixels().x, 18.0, title, subtitle, 20.0);
    draw_colour_bar(cr, {frame.pixels().right() + 30.0, frame.pixels().y, 24.0, frame.pixels().h}, map, -travel,
                    travel, ColourBarStyle{.label = "vertical displacement w (mm)", .tick_scale = mm});
    canvas.write_png(path);
  }

  MapLayout layout;
  Canvas canvas;
  PlotFrame frame;
  double travel;  // m
  ColourMap map{ColourMapKind::diverging};
};

}  // namespace

void write_strain_map_png(const std::filesystem::path& path, const AnalysisResult& r, StrainKind kind, double vmax,
                          int width) {
  if (!(vmax > 0.0)) vmax = auto_strain_scale(r, kind);
  const MapLayout layout = map_layout(r, width);
  Canvas canvas(width, layout.height);
  cairo_t* cr = canvas.cr();
  const Rect area = layout.area;
  const PlotFrame f = draw_strain_map(cr, area, r, kind, vmax);
  const std::string what = kind == StrainKind::total ? "maximum shear strain γmax (total)"
                                                     : "accumulated incremental maximum shear strain";
  const std::string smoothing = shows_smoothed(r, kind) ? "; " + smoothing_text(r) : std::string();
  draw_title(cr, f.pixels().x, 18.0, fmt::format("{}: {}", r.geometry.name, what),
             fmt::format("{}; strain from {}, drawn on the reference positions{}\n{}; dashed lines: traced band "
                         "centres (orange: branches)",
                         displacement_text(r), format_mm(r.reference_displacement), smoothing, view_text(r)),
             20.0);
  ColourBarStyle bar{.label = kind == StrainKind::total ? "γmax (-)" : "Σ Δγmax (-)", .extend_high = true};
  draw_colour_bar(cr, {f.pixels().right() + 30.0, f.pixels().y + 20.0, 24.0, f.pixels().h - 20.0},
                  ColourMap(ColourMapKind::viridis), 0.0, vmax, bar);
  canvas.write_png(path);
}

void write_displacement_contours_png(const std::filesystem::path& path, const AnalysisResult& r, int width) {
  DisplacementMap figure(r, width);
  cairo_t* cr = figure.canvas.cr();
  const PlotFrame& f = figure.frame;
  const double travel = figure.travel;
  const ColourMap& map = figure.map;
  const GridField& w = r.vertical_displacement;
  cairo_save(cr);
  f.clip(cr);
  cairo_set_source_rgb(cr, 0.93, 0.93, 0.93);
  cairo_paint(cr);
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
  const double h = w.grid.spacing;
  for (std::size_t j = 0; j < w.grid.nz; ++j) {
    for (std::size_t i = 0; i < w.grid.nx; ++i) {
      const double v = w.at(i, j);
      if (std::isnan(v)) continue;
      set_colour(cr, map.of(v, -travel, travel));
      const double x0 = f.px((w.grid.x(i) - 0.5 * h) * mm), x1 = f.px((w.grid.x(i) + 0.5 * h) * mm);
      const double y0 = f.py((w.grid.z(j) + 0.5 * h) * mm), y1 = f.py((w.grid.z(j) - 0.5 * h) * mm);
      cairo_rectangle(cr, std::floor(x0), std::floor(y0), std::ceil(x1) - std::floor(x0), std::ceil(y1) - std::floor(y0));
      cairo_fill(cr);
    }
  }
  cairo_set_antialias(cr, CAIRO_ANTIALIAS_DEFAULT);
  draw_base_and_trapdoor(cr, f, r);
  cairo_restore(cr);
  // Settlement contours (downward positive) at nice levels up to the largest settlement.
  GridField settlement = w;
  double largest = 0.0;
  for (double& v : settlement.value) {
    v = -v;
    if (std::isfinite(v)) largest = std::max(largest, v);
  }
  std::vector<double> levels;
  for (double v : nice_ticks(0.0, largest * mm, 8)) {
    if (v > 0.0) levels.push_back(v / mm);
  }
  const double step_mm = levels.size() > 1 ? (levels[1] - levels[0]) * mm : 1.0;
  draw_contours(cr, f, settlement, levels, [&](double v) { return format_tick(v * mm, step_mm); }, ContourStyle{});
  figure.finish(path, fmt::format("{}: settlement contours (mm)", r.geometry.name),
                fmt::format("{}; colour: vertical displacement w on the reference positions\ngrid {}; {}",
                            displacement_text(r), format_mm(r.settings.grid_spacing), view_text(r)));
}

void write_particles_png(const std::filesystem::path& path, const AnalysisResult& r, int width) {
  DisplacementMap figure(r, width);
  cairo_t* cr = figure.canvas.cr();
  const PlotFrame& f = figure.frame;
  cairo_save(cr);
  f.clip(cr);
  const double scale = f.scale_x();
  for (std::size_t k = 0; k < r.points.size(); ++k) {
    const Point2 p = r.points.position[k] + r.points.displacement[k];
    cairo_new_sub_path(cr);
    cairo_arc(cr, f.px(p.x * mm), f.py(p.z * mm), r.radius[k] * mm * scale, 0.0, 2.0 * M_PI);
    set_colour(cr, figure.map.of(r.points.displacement[k].z, -figure.travel, figure.travel));
    cairo_fill_preserve(cr);
    cairo_set_source_rgba(cr, 0.2, 0.2, 0.2, 0.7);
    cairo_set_line_width(cr, 0.8);
    cairo_stroke(cr);
  }
  draw_base_and_trapdoor(cr, f, r);
  cairo_restore(cr);
  figure.finish(path, fmt::format("{}: particles coloured by vertical displacement", r.geometry.name),
                fmt::format("{}\ncurrent positions, radius to scale; {}", displacement_text(r), view_text(r)));
}

void write_strain_panel_png(const std::filesystem::path& path, const std::vector<const AnalysisResult*>& results,
                            double vmax, int panel_width) {
  if (results.empty()) return;
  if (!(vmax > 0.0)) {
    for (const auto* r : results) vmax = std::max(vmax, auto_strain_scale(*r));
  }
  const double font = 15.0, left = left_margin * font / 16.0, bottom = bottom_margin * font / 16.0;
  const double top = 110.0, right = 150.0, gap = 10.0;
  double plot_h = 0.0;
  for (const auto* r : results) plot_h = std::max(plot_h, map_height_for_width(*r, panel_width - left));
  plot_h = std::min(plot_h, 900.0);
  const int width = static_cast<int>(results.size() * (panel_width + gap) + right);
  const int height = static_cast<int>(top + plot_h + bottom + 10.0);
  Canvas canvas(width, height);
  cairo_t* cr = canvas.cr();
  double frame_top = top, frame_bottom = top + plot_h;
  for (std::size_t k = 0; k < results.size(); ++k) {
    const AnalysisResult& r = *results[k];
    const Rect area{k * (panel_width + gap), top, static_cast<double>(panel_width), plot_h + bottom};
    const PlotFrame f = draw_strain_map(cr, area, r, StrainKind::total, vmax, font);
    frame_bottom = f.pixels().bottom();
    TextStyle name{.size = 17.0, .bold = true, .h = HAlign::centre, .v = VAlign::bottom};
    draw_text(cr, fmt::format("({}) {}", static_cast<char>('a' + k), r.geometry.name), f.pixels().x + 0.5 * f.pixels().w,
              f.pixels().y - 26.0, name);
    TextStyle sub{.size = 14.0, .colour = {0.3, 0.3, 0.3}, .h = HAlign::centre, .v = VAlign::bottom};
    draw_text(cr, fmt::format("δ = {}, δ/B = {:.2f}", format_mm(r.trapdoor_travel()),
                              r.trapdoor_travel() / r.geometry.trapdoor.width),
              f.pixels().x + 0.5 * f.pixels().w, f.pixels().y - 6.0, sub);
  }
  const bool smoothed = !results.empty() && shows_smoothed(*results.front(), StrainKind::total);
  draw_text(cr,
            fmt::format("Maximum shear strain γmax (total{}), one colour scale",
                        smoothed ? fmt::format(", smoothed over a Gaussian of {:g} d",
                                               results.front()->settings.bands.smoothing_diameters)
                                 : std::string()),
            20.0, 16.0,
            TextStyle{.size = 20.0, .bold = true, .v = VAlign::top});
  ColourBarStyle bar{.label = "γmax (-)", .extend_high = true};
  draw_colour_bar(cr, {width - right + 30.0, frame_top + 20.0, 24.0, frame_bottom - frame_top - 20.0},
                  ColourMap(ColourMapKind::viridis), 0.0, vmax, bar);
  canvas.write_png(path);
}

}  // namespace trapdem::plot
