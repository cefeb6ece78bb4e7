#include "piv/piv_output.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>
#include <opencv2/imgproc.hpp>

#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "plot/piv_figures.hpp"

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

// --- what the figures draw, as plain data (src/plot/piv_figures.hpp) ----------------------------

plot::Photograph photograph(const cv::Mat& grey8) {
  if (grey8.type() != CV_8UC1) throw std::invalid_argument("a figure's photograph must be 8-bit grey (to_grey8)");
  plot::Photograph p{grey8.cols, grey8.rows, {}};
  p.grey.reserve(grey8.total());
  for (int y = 0; y < grey8.rows; ++y) {
    const std::uint8_t* row = grey8.ptr<std::uint8_t>(y);
    p.grey.insert(p.grey.end(), row, row + grey8.cols);
  }
  return p;
}

plot::StrainTriangles strain_triangles(const PivStrainField& s) {
  return {s.position, s.displacement, s.mesh, s.max_shear};
}

// Poor texture in image 1 (the figures' photograph) counts as such also when the subset was lost at
// a reference update since: poorly textured subsets carry no trusted position into a new reference.
plot::SubsetMark subset_mark(const PivResult& r, std::size_t k, std::size_t i) {
  const SubsetStatus status = r.image[k].subset[i].status;
  if (status == SubsetStatus::valid) return plot::SubsetMark::valid;
  if (status == SubsetStatus::low_texture) return plot::SubsetMark::poor_texture;
  if (status == SubsetStatus::lost && r.image[0].subset[i].status == SubsetStatus::low_texture)
    return plot::SubsetMark::poor_texture_lost;
  return plot::SubsetMark::flagged;
}

plot::PivFigureData piv_figure_data(const PivFigureInput& in) {
  const PivResult& r = *in.result;
  const std::size_t k = r.image_count() - 1;  // the figures show the last image
  plot::PivFigureData d;
  d.title = in.title;
  d.unit = in.unit;
  d.first_image = photograph(in.first_image);
  d.last_image = photograph(in.last_image);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) d.pixel_to_plot[3 * i + j] = in.to_plot.matrix(i, j);
  d.image_number = k + 1;
  d.grid_step = r.grid.step;
  for (std::size_t i = 0; i < r.grid.size(); ++i) {
    const SubsetMeasurement& m = r.image[k].subset[i];
    d.subsets.push_back({r.grid.centre[i].x, r.grid.centre[i].y, r.grid.column_of(i), r.grid.row_of(i), m.u, m.v,
                         m.zncc, subset_mark(r, k, i)});
  }
  d.total_strain = strain_triangles(in.strain->total[k]);
  d.incremental_strain = strain_triangles(in.strain->incremental[k]);
  return d;
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
  const plot::PivFigureData data = piv_figure_data(in);
  fs::create_directories(dir);
  std::vector<fs::path> out;
  for (const char* name :
       {"shear_strain", "shear_strain_incremental", "vertical_displacement", "vectors", "correlation_quality"}) {
    out.push_back(plot::with_format(dir / name, in.format));
  }
  plot::write_piv_strain_figure(out[0], data, false);
  plot::write_piv_strain_figure(out[1], data, true);
  plot::write_piv_vertical_displacement_figure(out[2], data, in.settlement_levels);
  plot::write_piv_vectors_figure(out[3], data);
  plot::write_piv_quality_figure(out[4], data);
  return out;
}

}  // namespace trapdem
