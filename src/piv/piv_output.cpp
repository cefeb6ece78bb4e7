#include "piv/piv_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "analysis/grid_interpolation.hpp"
#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "plot/axes.hpp"
#include "plot/canvas.hpp"
#include "plot/colour_bar.hpp"
#include "plot/colour_map.hpp"
#include "plot/contour_plot.hpp"
#include "plot/text.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

PivStrainField strain_or_empty(const std::function<PivStrainField()>& f) {
  try {
    return f();
  } catch (const InputError&) {
    return {};  // too few valid subsets for a triangle
  }
}

std::string image_group_name(std::size_t k) { return fmt::format("{:06d}", k + 1); }

void write_strain_group(const Hdf5Group& parent, const std::string& name, const PivStrainField& s,
                        const std::string& unit) {
  const Hdf5Group g = parent.create_group(name);
  std::vector<std::uint32_t> subset(s.subset.begin(), s.subset.end());
  std::vector<std::uint32_t> tri;
  tri.reserve(3 * s.mesh.size());
  for (const auto& t : s.mesh.triangles) {
    for (std::size_t n : t) tri.push_back(static_cast<std::uint32_t>(n));
  }
  std::vector<double> x, z, dx, dz;
  for (std::size_t i = 0; i < s.position.size(); ++i) {
    x.push_back(s.position[i].x);
    z.push_back(s.position[i].z);
    dx.push_back(s.displacement[i].x);
    dz.push_back(s.displacement[i].z);
  }
  g.write_uint32s("node_subset", subset);
  g.write_doubles("node_x", x, unit);
  g.write_doubles("node_z", z, unit);
  g.write_doubles("node_dx", dx, unit);
  g.write_doubles("node_dz", dz, unit);
  g.write_uint32s("triangles", tri);
  g.write_doubles("max_shear", s.max_shear);
  g.write_doubles("volumetric", s.volumetric);
  g.set_string_attribute("layout", "triangles: 3 node indices per triangle (into node_*), flattened; strains "
                                   "compression positive, engineering shear");
}

// --- figures -----------------------------------------------------------------------------------

using plot::PlotFrame;
using plot::Range1;
using plot::Rect;

struct Figure {
  PlotFrame frame;
  cairo_matrix_t pixel_to_device;  // image pixel (x, y) -> canvas
};

cv::Point2d plot_point(const PixelToModel& t, cv::Point2d p) { return to_model(t, p); }

Figure make_figure_frame(const PivFigureInput& in, Rect space) {
  const int w = in.first_image.cols, h = in.first_image.rows;
  double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
  for (cv::Point2d c : {cv::Point2d(-0.5, -0.5), cv::Point2d(w - 0.5, -0.5), cv::Point2d(-0.5, h - 0.5),
                        cv::Point2d(w - 0.5, h - 0.5)}) {
    const cv::Point2d m = plot_point(in.to_plot, c);
    x0 = std::min(x0, m.x), x1 = std::max(x1, m.x), z0 = std::min(z0, m.y), z1 = std::max(z1, m.y);
  }
  const Range1 xr{x0, x1}, zr{z0, z1};
  const Rect plot = plot::fit_equal_aspect(space, xr, zr);
  Figure f{PlotFrame(plot, xr, zr), {}};
  // Affine part of the transform (a projective one is approximated by it for the background).
  const cv::Matx33d& m = in.to_plot.matrix;
  const double sx = plot.w / xr.span(), sz = plot.h / zr.span();
  const double fx0 = plot.x - xr.lo * sx, fy0 = plot.bottom() + zr.lo * sz;
  const double n = m(2, 2);
  cairo_matrix_init(&f.pixel_to_device, sx * m(0, 0) / n, -sz * m(1, 0) / n, sx * m(0, 1) / n, -sz * m(1, 1) / n,
                    fx0 + sx * m(0, 2) / n, fy0 - sz * m(1, 2) / n);
  return f;
}

cv::Point2d device(const Figure& f, cv::Point2d plot_xy) { return {f.frame.px(plot_xy.x), f.frame.py(plot_xy.y)}; }

// The photograph under the plot frame; `fade` paints white over it (0: none).
void draw_photograph(cairo_t* cr, const Figure& f, const cv::Mat& grey8, double fade) {
  cv::Mat bgra;
  cv::cvtColor(grey8, bgra, cv::COLOR_GRAY2BGRA);
  cairo_surface_t* s = cairo_image_surface_create_for_data(bgra.data, CAIRO_FORMAT_RGB24, bgra.cols, bgra.rows,
                                                           static_cast<int>(bgra.step));
  cairo_save(cr);
  f.frame.clip(cr);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_paint(cr);
  cairo_transform(cr, &f.pixel_to_device);
  cairo_set_source_surface(cr, s, -0.5, -0.5);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
  cairo_paint(cr);
  cairo_restore(cr);
  if (fade > 0.0) {
    cairo_save(cr);
    f.frame.clip(cr);
    cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, fade);
    cairo_paint(cr);
    cairo_restore(cr);
  }
  cairo_surface_finish(s);
  cairo_surface_destroy(s);
}

struct Layout {
  static constexpr double width = 1400.0, top = 96.0, left = 90.0, right = 170.0, bottom = 70.0;
};

// Canvas height for a frame of the image's aspect ratio in the standard layout.
int canvas_height(const PivFigureInput& in) {
  const Figure probe = make_figure_frame(in, {Layout::left, Layout::top, Layout::width - Layout::left - Layout::right,
                                              1e6});
  const double plot_h = probe.frame.pixels().h;
  return static_cast<int>(Layout::top + std::min(plot_h, 1100.0) + Layout::bottom);
}

Figure standard_frame(const PivFigureInput& in, int height) {
  return make_figure_frame(in, {Layout::left, Layout::top, Layout::width - Layout::left - Layout::right,
                                height - Layout::top - Layout::bottom});
}

void draw_titles(cairo_t* cr, const std::string& title, const std::string& subtitle) {
  plot::TextStyle t;
  t.size = 24.0;
  t.bold = true;
  plot::draw_text(cr, title, 20.0, 34.0, t);
  plot::TextStyle s;
  s.size = 16.0;
  s.colour = {0.25, 0.25, 0.25};
  plot::draw_text(cr, subtitle, 20.0, 64.0, s);
}

void draw_frame_axes(cairo_t* cr, const Figure& f, const std::string& unit) {
  plot::AxesStyle a;
  a.x_label = fmt::format("x ({})", unit);
  a.y_label = unit == "px" ? "-y (px, image rows counted upward)" : fmt::format("z ({}), up", unit);
  a.font_size = 15.0;
  plot::draw_axes(cr, f.frame, a);
}

Rect colour_bar_rect(const Figure& f) {
  const Rect& p = f.frame.pixels();
  return {p.right() + 22.0, p.y + 0.1 * p.h, 22.0, 0.8 * p.h};
}

double quantile(std::vector<double> v, double q) {
  v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
  if (v.empty()) return nan;
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

double nice_ceiling(double q) {
  if (!(q > 0.0)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(q)));
  for (double m : {1.0, 2.0, 2.5, 5.0, 10.0}) {
    if (m * p >= q) return m * p;
  }
  return 10.0 * p;
}

std::size_t last_image(const PivResult& r) { return r.image_count() - 1; }

fs::path write_strain_figure(const fs::path& dir, const PivFigureInput& in, bool incremental) {
  const std::size_t k = last_image(*in.result);
  const PivStrainField& s = incremental ? in.strain->incremental[k] : in.strain->total[k];
  const int height = canvas_height(in);
  plot::Canvas canvas(static_cast<int>(Layout::width), height);
  cairo_t* cr = canvas.cr();
  const Figure f = standard_frame(in, height);
  draw_photograph(cr, f, in.last_image, 0.0);
  const double vmax = nice_ceiling(quantile(s.max_shear, 0.95));
  const plot::ColourMap map(plot::ColourMapKind::viridis);
  cairo_save(cr);
  f.frame.clip(cr);
  // Each soil element where it is in the last image (incremental: the previous image + increment
  // ends there too, for the incremental positions are those of image k - 1).
  for (std::size_t t = 0; t < s.mesh.size(); ++t) {
    const auto& tri = s.mesh.triangles[t];
    for (int c = 0; c < 3; ++c) {
      const Point2 p = s.position[tri[c]] + s.displacement[tri[c]];
      const cv::Point2d d = device(f, {p.x, p.z});
      if (c == 0) cairo_move_to(cr, d.x, d.y);
      else cairo_line_to(cr, d.x, d.y);
    }
    cairo_close_path(cr);
    plot::set_colour(cr, map.of(s.max_shear[t], 0.0, vmax), 0.72);
    cairo_fill_preserve(cr);
    cairo_set_line_width(cr, 0.6);
    cairo_stroke(cr);
  }
  cairo_restore(cr);
  draw_frame_axes(cr, f, in.unit);
  plot::ColourBarStyle cb;
  cb.label = incremental ? "incremental max shear strain γmax (-)" : "max shear strain γmax (-)";
  cb.extend_high = true;
  plot::draw_colour_bar(cr, colour_bar_rect(f), map, 0.0, vmax, cb);
  const std::size_t valid = count_valid(*in.result, k);
  draw_titles(cr,
              fmt::format("{}: {} shear strain", in.title, incremental ? "incremental" : "total"),
              fmt::format("image {} {} image {}, over image {}; {} of {} subsets valid; blank: no valid triangle",
                          incremental ? k : 1, "to", k + 1, k + 1, valid,
                          in.result->grid.size()));
  const fs::path path = dir / (incremental ? "shear_strain_incremental.png" : "shear_strain.png");
  canvas.write_png(path);
  return path;
}

fs::path write_contour_figure(const fs::path& dir, const PivFigureInput& in) {
  const std::size_t k = last_image(*in.result);
  const PivStrainField& s = in.strain->total[k];
  const int height = canvas_height(in);
  plot::Canvas canvas(static_cast<int>(Layout::width), height);
  cairo_t* cr = canvas.cr();
  const Figure f = standard_frame(in, height);
  draw_photograph(cr, f, in.first_image, 0.55);
  const plot::ColourMap map(plot::ColourMapKind::diverging);
  double top = 0.0;
  std::vector<double> dz;
  for (const auto& d : s.displacement) {
    dz.push_back(d.z);
    top = std::max(top, std::abs(d.z));
  }
  top = nice_ceiling(top);
  if (!s.mesh.triangles.empty()) {
    // Grid spacing: half a subset step in plot units.
    const double plot_per_px = std::sqrt(std::abs(in.to_plot.matrix(0, 0) * in.to_plot.matrix(1, 1) -
                                                  in.to_plot.matrix(0, 1) * in.to_plot.matrix(1, 0)));
    const double spacing = 0.5 * in.result->grid.step * plot_per_px;
    const GridSpec grid = grid_covering(s.position, spacing);
    const GridField field = interpolate_nodal_field(s.mesh, s.position, dz, grid);
    cairo_save(cr);
    f.frame.clip(cr);
    cairo_set_antialias(cr, CAIRO_ANTIALIAS_NONE);
    for (std::size_t j = 0; j < grid.nz; ++j) {
      for (std::size_t i = 0; i < grid.nx; ++i) {
        const double v = field.at(i, j);
        if (!std::isfinite(v)) continue;
        const double x0 = f.frame.px(grid.x(i) - 0.5 * spacing), x1 = f.frame.px(grid.x(i) + 0.5 * spacing);
        const double y0 = f.frame.py(grid.z(j) + 0.5 * spacing), y1 = f.frame.py(grid.z(j) - 0.5 * spacing);
        plot::set_colour(cr, map.of(v, -top, top), 0.75);
        cairo_rectangle(cr, x0, y0, x1 - x0 + 0.5, y1 - y0 + 0.5);
        cairo_fill(cr);
      }
    }
    cairo_restore(cr);
    const double step = plot::nice_step(2.0 * top, 10);
    std::vector<double> levels;
    for (double l = -top + step; l < top - 0.5 * step; l += step) {
      if (std::abs(l) > 0.25 * step) levels.push_back(l);
    }
    plot::ContourStyle style;
    style.coordinate_scale = 1.0;
    cairo_save(cr);
    f.frame.clip(cr);
    plot::draw_contours(cr, f.frame, field, levels, [&](double v) { return plot::format_tick(v, step); }, style);
    cairo_restore(cr);
  }
  draw_frame_axes(cr, f, in.unit);
  plot::ColourBarStyle cb;
  cb.label = fmt::format("upward displacement ({})", in.unit);
  plot::draw_colour_bar(cr, colour_bar_rect(f), map, -top, top, cb);
  draw_titles(cr, fmt::format("{}: vertical displacement", in.title),
              fmt::format("image 1 to image {}, at the subsets' positions in image 1 (shown); heave positive, "
                          "settlement negative",
                          k + 1));
  const fs::path path = dir / "vertical_displacement.png";
  canvas.write_png(path);
  return path;
}

void draw_arrow(cairo_t* cr, cv::Point2d a, cv::Point2d b, double head) {
  cairo_move_to(cr, a.x, a.y);
  cairo_line_to(cr, b.x, b.y);
  cairo_stroke(cr);
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  if (len < 1e-9) return;
  const double ux = (b.x - a.x) / len, uy = (b.y - a.y) / len;
  const double hl = std::min(head, 0.5 * len);
  cairo_move_to(cr, b.x, b.y);
  cairo_line_to(cr, b.x - hl * ux + 0.5 * hl * uy, b.y - hl * uy - 0.5 * hl * ux);
  cairo_line_to(cr, b.x - hl * ux - 0.5 * hl * uy, b.y - hl * uy + 0.5 * hl * ux);
  cairo_close_path(cr);
  cairo_fill(cr);
}

fs::path write_vector_figure(const fs::path& dir, const PivFigureInput& in) {
  const PivResult& r = *in.result;
  const std::size_t k = last_image(r);
  const int height = canvas_height(in);
  plot::Canvas canvas(static_cast<int>(Layout::width), height);
  cairo_t* cr = canvas.cr();
  const Figure f = standard_frame(in, height);
  draw_photograph(cr, f, in.first_image, 0.35);
  // Device pixels per image pixel, and arrows at least 14 device px apart.
  const double dev_per_px = std::sqrt(std::abs(f.pixel_to_device.xx * f.pixel_to_device.yy -
                                               f.pixel_to_device.xy * f.pixel_to_device.yx));
  const int stride = std::max(1, static_cast<int>(std::ceil(14.0 / (r.grid.step * dev_per_px))));
  std::vector<double> lengths;
  for (const auto& m : r.image[k].subset) {
    if (m.is_valid()) lengths.push_back(std::hypot(m.u, m.v));
  }
  const double typical = quantile(lengths, 0.95);
  const double spacing_dev = stride * r.grid.step * dev_per_px;
  const double magnify = typical > 0.0 ? 1.6 * spacing_dev / (typical * dev_per_px) : 1.0;
  const double shown = magnify;
  cairo_save(cr);
  f.frame.clip(cr);
  cairo_set_line_width(cr, 1.4);
  cairo_set_source_rgb(cr, 0.80, 0.05, 0.05);
  for (std::size_t i = 0; i < r.grid.size(); ++i) {
    if (r.grid.column_of(i) % stride || r.grid.row_of(i) % stride) continue;
    const auto& m = r.image[k].subset[i];
    if (!m.is_valid()) continue;
    const cv::Point2d c = r.grid.centre[i];
    double ax = c.x, ay = c.y, bx = c.x + shown * m.u, by = c.y + shown * m.v;
    cairo_matrix_transform_point(&f.pixel_to_device, &ax, &ay);
    cairo_matrix_transform_point(&f.pixel_to_device, &bx, &by);
    draw_arrow(cr, {ax, ay}, {bx, by}, 7.0);
  }
  cairo_restore(cr);
  draw_frame_axes(cr, f, in.unit);
  draw_titles(cr, fmt::format("{}: displacement vectors", in.title),
              fmt::format("image 1 to image {}, drawn {:.3g} times their length (95th percentile {:.3g} px); "
                          "every {} subset(s)",
                          k + 1, shown, typical, stride));
  const fs::path path = dir / "vectors.png";
  canvas.write_png(path);
  return path;
}

fs::path write_quality_figure(const fs::path& dir, const PivFigureInput& in) {
  const PivResult& r = *in.result;
  const std::size_t k = last_image(r);
  const int height = canvas_height(in);
  plot::Canvas canvas(static_cast<int>(Layout::width), height);
  cairo_t* cr = canvas.cr();
  const Figure f = standard_frame(in, height);
  draw_photograph(cr, f, in.first_image, 0.0);
  const plot::ColourMap map(plot::ColourMapKind::viridis);
  const double lo = 0.6, hi = 1.0;
  const double half = 0.5 * r.grid.step;
  std::size_t flagged = 0, poor = 0, poor_lost = 0;
  cairo_save(cr);
  f.frame.clip(cr);
  for (std::size_t i = 0; i < r.grid.size(); ++i) {
    const auto& m = r.image[k].subset[i];
    const cv::Point2d c = r.grid.centre[i];
    double x0 = c.x - half, y0 = c.y - half, x1 = c.x + half, y1 = c.y + half;
    cairo_matrix_transform_point(&f.pixel_to_device, &x0, &y0);
    cairo_matrix_transform_point(&f.pixel_to_device, &x1, &y1);
    const double l = std::min(x0, x1), t = std::min(y0, y1), w = std::abs(x1 - x0), h = std::abs(y1 - y0);
    // Poor texture in image 1 (the figure's photograph): grey, also when the subset was lost at a
    // reference update since (poorly textured subsets carry no trusted position into a new reference).
    const bool lost_poor = m.status == SubsetStatus::lost && r.image[0].subset[i].status == SubsetStatus::low_texture;
    if (m.status == SubsetStatus::low_texture || lost_poor) {
      ++poor;
      poor_lost += lost_poor;
      cairo_set_source_rgba(cr, 0.55, 0.55, 0.55, 0.75);
      cairo_rectangle(cr, l, t, w, h);
      cairo_fill(cr);
      continue;
    }
    if (std::isfinite(m.zncc)) {
      plot::set_colour(cr, map.of(m.zncc, lo, hi), 0.8);
      cairo_rectangle(cr, l, t, w, h);
      cairo_fill(cr);
    }
    if (!m.is_valid()) {
      ++flagged;
      const double cx = l + 0.5 * w, cy = t + 0.5 * h, a = std::max(2.0, 0.35 * std::min(w, h));
      cairo_set_source_rgb(cr, 0.9, 0.0, 0.0);
      cairo_set_line_width(cr, 1.5);
      cairo_move_to(cr, cx - a, cy - a);
      cairo_line_to(cr, cx + a, cy + a);
      cairo_move_to(cr, cx - a, cy + a);
      cairo_line_to(cr, cx + a, cy - a);
      cairo_stroke(cr);
    }
  }
  cairo_restore(cr);
  draw_frame_axes(cr, f, in.unit);
  plot::ColourBarStyle cb;
  cb.label = "ZNCC (-)";
  plot::draw_colour_bar(cr, colour_bar_rect(f), map, lo, hi, cb);
  draw_titles(cr, fmt::format("{}: correlation quality, image {}", in.title, k + 1),
              fmt::format("ZNCC per subset; grey: too little texture in image 1 ({}; {} of them lost since); red x: "
                          "other flagged (low correlation, not converged, left image, lost: {})",
                          poor, poor_lost, flagged));
  const fs::path path = dir / "correlation_quality.png";
  canvas.write_png(path);
  return path;
}

}  // namespace

cv::Mat to_grey8(const cv::Mat& image) {
  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else if (image.channels() == 4) cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  cv::Mat out;
  if (grey.depth() == CV_16U) grey.convertTo(out, CV_8U, 1.0 / 257.0);
  else if (grey.depth() == CV_8U) out = grey.clone();
  else grey.convertTo(out, CV_8U);
  return out;
}

PivStrainSeries compute_piv_strain(const PivResult& result, const PixelToModel& t) {
  PivStrainSeries s;
  s.total.resize(result.image_count());
  s.incremental.resize(result.image_count());
  for (std::size_t k = 1; k < result.image_count(); ++k) {
    s.total[k] = strain_or_empty([&] { return piv_total_strain(result, k, t); });
    s.incremental[k] = strain_or_empty([&] { return piv_incremental_strain(result, k, t); });
  }
  return s;
}

void write_piv_h5(const fs::path& path, const PivResult& r, const std::vector<std::string>& names,
                  const std::optional<PixelToModel>& model, const std::string& unit, const PivStrainSeries& strain) {
  Hdf5File file = Hdf5File::create_in_memory(path);
  file.set_string_attribute("format", "trapdem piv 1");
  file.set_string_attribute("status_codes",
                            "0 valid, 1 low_texture, 2 low_correlation, 3 not_converged, 4 left_image, 5 lost");
  const Hdf5Group grid = file.create_group("grid");
  std::vector<double> x, y;
  for (const auto& c : r.grid.centre) x.push_back(c.x), y.push_back(c.y);
  grid.write_doubles("x_px", x, "px");
  grid.write_doubles("y_px", y, "px");
  grid.set_int_attribute("subset_size", r.grid.subset_size);
  grid.set_int_attribute("step", r.grid.step);
  grid.set_int_attribute("columns", r.grid.columns);
  grid.set_int_attribute("rows", r.grid.rows);
  if (model) {
    const Hdf5Group m = file.create_group("model");
    std::vector<double> flat;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) flat.push_back(model->matrix(i, j));
    m.write_doubles("pixel_to_model", flat);
    m.set_string_attribute("unit", unit);
    m.set_string_attribute("convention", "(X w, Z w, w) = M (x, y, 1), row-major 3x3; x right, z up");
  }
  const Hdf5Group images = file.create_group("images");
  for (std::size_t k = 0; k < r.image_count(); ++k) {
    const Hdf5Group g = images.create_group(image_group_name(k));
    const auto& im = r.image[k];
    std::vector<double> u, v, zncc, xm, zm, um, wm;
    std::vector<std::uint8_t> status, valid;
    for (std::size_t i = 0; i < r.grid.size(); ++i) {
      const auto& s = im.subset[i];
      u.push_back(s.u);
      v.push_back(s.v);
      zncc.push_back(s.zncc);
      status.push_back(static_cast<std::uint8_t>(s.status));
      valid.push_back(s.is_valid() ? 1 : 0);
      if (model) {
        const cv::Point2d c = r.grid.centre[i];
        const cv::Point2d m0 = to_model(*model, c);
        if (std::isfinite(s.u) && std::isfinite(s.v)) {
          const cv::Point2d m1 = to_model(*model, {c.x + s.u, c.y + s.v});
          xm.push_back(m1.x), zm.push_back(m1.y), um.push_back(m1.x - m0.x), wm.push_back(m1.y - m0.y);
        } else {
          xm.push_back(nan), zm.push_back(nan), um.push_back(nan), wm.push_back(nan);
        }
      }
    }
    g.write_doubles("u_px", u, "px");
    g.write_doubles("v_px", v, "px");
    g.write_doubles("zncc", zncc);
    g.write_uint8s("status", status);
    g.write_uint8s("valid", valid);
    if (model) {
      g.write_doubles("x_model", xm, unit);
      g.write_doubles("z_model", zm, unit);
      g.write_doubles("u_model", um, unit);
      g.write_doubles("w_model", wm, unit);
    }
    g.set_string_attribute("name", k < names.size() ? names[k] : "");
    g.set_int_attribute("reference_image", static_cast<std::int64_t>(im.reference + 1));
    g.set_double_attribute("seconds", im.seconds);
    g.set_int_attribute("valid_count", static_cast<std::int64_t>(count_valid(r, k)));
    if (k >= 1 && k < strain.total.size()) {
      write_strain_group(g, "strain_total", strain.total[k], model ? unit : "px");
      write_strain_group(g, "strain_incremental", strain.incremental[k], model ? unit : "px");
    }
  }
  write_atomically(path, [&](const fs::path& tmp) { file.write_image(tmp); });
}

std::vector<fs::path> write_piv_figures(const fs::path& dir, const PivFigureInput& in) {
  if (!in.result || !in.strain || in.result->image_count() < 2) return {};
  fs::create_directories(dir);
  std::vector<fs::path> out;
  out.push_back(write_strain_figure(dir, in, false));
  out.push_back(write_strain_figure(dir, in, true));
  out.push_back(write_contour_figure(dir, in));
  out.push_back(write_vector_figure(dir, in));
  out.push_back(write_quality_figure(dir, in));
  return out;
}

}  // namespace trapdem
