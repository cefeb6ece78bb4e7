#include "analysis/dem_piv_comparison.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "analysis/delaunay.hpp"
#include "analysis/grid_interpolation.hpp"
#include "core/length_text.hpp"
#include "analysis/triangle_filter.hpp"
#include "core/errors.hpp"
#include "io/hdf5_file.hpp"

namespace trapdem {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -std::numeric_limits<double>::infinity();
  double z0 = std::numeric_limits<double>::infinity(), z1 = -std::numeric_limits<double>::infinity();
};

Box bounding_box(const std::vector<Point2>& p) {
  Box b;
  for (const Point2& q : p) {
    b.x0 = std::min(b.x0, q.x), b.x1 = std::max(b.x1, q.x);
    b.z0 = std::min(b.z0, q.z), b.z1 = std::max(b.z1, q.z);
  }
  return b;
}

double metres_per_unit(const std::string& unit, const std::string& where) {
  if (unit == "mm") return 1e-3;
  if (unit == "cm") return 1e-2;
  if (unit == "m") return 1.0;
  throw InputError(fmt::format("{}: model unit '{}': expected mm, cm or m", where, unit));
}

}  // namespace

GridSpec common_grid(const std::vector<Point2>& a, const std::vector<Point2>& b, double spacing) {
  if (!(spacing > 0.0)) throw InputError("the comparison grid spacing must be positive");
  if (a.empty() || b.empty()) throw InputError("a displacement field to compare has no points");
  const Box ba = bounding_box(a), bb = bounding_box(b);
  const double x0 = std::max(ba.x0, bb.x0), x1 = std::min(ba.x1, bb.x1);
  const double z0 = std::max(ba.z0, bb.z0), z1 = std::min(ba.z1, bb.z1);
  if (!(x0 <= x1 && z0 <= z1)) {
    throw InputError(fmt::format("the DEM and PIV fields do not overlap: DEM x {} to {}, z {} to {}; PIV x {} to {}, "
                                 "z {} to {} (trapdoor centre at 0; check the PIV model coordinates)",
                                 format_mm(ba.x0), format_mm(ba.x1), format_mm(ba.z0), format_mm(ba.z1),
                                 format_mm(bb.x0), format_mm(bb.x1), format_mm(bb.z0), format_mm(bb.z1)));
  }
  check_grid_memory(x1 - x0, z1 - z0, spacing, "the comparison grid spacing");
  GridSpec g;
  g.spacing = spacing;
  const double i0 = std::ceil(x0 / spacing - 1e-9), i1 = std::floor(x1 / spacing + 1e-9);
  const double j0 = std::ceil(z0 / spacing - 1e-9), j1 = std::floor(z1 / spacing + 1e-9);
  if (i1 < i0 || j1 < j0) throw InputError("the DEM and PIV fields overlap by less than one grid spacing");
  g.x0 = i0 * spacing;
  g.z0 = j0 * spacing;
  g.nx = static_cast<std::size_t>(i1 - i0) + 1;
  g.nz = static_cast<std::size_t>(j1 - j0) + 1;
  return g;
}

GridField interpolate_scattered(const ScatteredDisplacement& field, const GridSpec& grid,
                                double max_edge_in_spacings) {
  if (field.position.size() != field.w.size()) throw InputError("scattered field: positions and values differ in count");
  if (field.position.size() < 3) {
    throw InputError(fmt::format("a displacement field has {} points: at least three are needed", field.position.size()));
  }
  if (!(field.spacing > 0.0)) throw InputError("scattered field: the point spacing must be positive");
  TriangleFilterSettings f;
  f.mean_diameter = field.spacing;
  f.max_edge_in_diameters = max_edge_in_spacings;
  const FilteredMesh mesh = filter_triangles(delaunay_triangulation(field.position), field.position, f);
  return interpolate_nodal_field(mesh.mesh, field.position, field.w, grid);
}

FieldComparison compare_fields(const GridField& a, const GridField& b, double delta) {
  if (a.grid.nx != b.grid.nx || a.grid.nz != b.grid.nz || a.grid.spacing != b.grid.spacing ||
      a.value.size() != b.value.size()) {
    throw InputError("the fields to compare are not on the same grid");
  }
  if (!(delta > 0.0)) throw InputError("the trapdoor displacement for the normalisation must be positive");
  FieldComparison c;
  c.grid_nodes = a.value.size();
  c.trapdoor_displacement = delta;
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t k = 0; k < a.value.size(); ++k) {
    if (!std::isfinite(a.value[k]) || !std::isfinite(b.value[k])) continue;
    const double d = a.value[k] - b.value[k];
    sum += d, sum2 += d * d;
    c.max_abs = std::max(c.max_abs, std::abs(d));
    ++c.compared;
  }
  if (c.compared == 0) {
    throw InputError("the DEM and PIV fields share no grid node (no overlap of the areas they cover)");
  }
  const double n = static_cast<double>(c.compared);
  c.rms = std::sqrt(sum2 / n);
  c.bias = sum / n;
  c.coverage = n / static_cast<double>(c.grid_nodes);
  return c;
}

void mask_to_common(GridField& a, GridField& b) {
  const std::size_t n = std::min(a.value.size(), b.value.size());
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(a.value[k]) || !std::isfinite(b.value[k])) a.value[k] = b.value[k] = nan;
  }
}

std::vector<std::string> piv_image_names(const std::filesystem::path& piv_h5) {
  if (!std::filesystem::exists(piv_h5)) {
    throw InputError(fmt::format("{}: not found (run `trapdem piv ... --out DIR` first; for DEM camera images the "
                                 "command is in camera/scale.txt)",
                                 piv_h5.string()));
  }
  const Hdf5File file = Hdf5File::open_read(piv_h5);
  const Hdf5Group images = file.group("images");
  std::vector<std::string> names;
  for (const std::string& child : images.children()) {
    const Hdf5Group g = images.group(child);
    names.push_back(g.has_attribute("name") ? g.string_attribute("name") : std::string());
  }
  return names;
}

ScatteredDisplacement read_piv_vertical_displacement(const std::filesystem::path& piv_h5, std::size_t reference_image,
                                                     std::size_t image, Point2 origin) {
  const std::vector<std::string> names = piv_image_names(piv_h5);
  const Hdf5File file = Hdf5File::open_read(piv_h5);
  if (!file.has("model")) {
    throw InputError(fmt::format("{}: no model coordinates (run `trapdem piv` with --scale MM_PER_PX --origin X,Z or "
                                 "--control-points FILE)",
                                 piv_h5.string()));
  }
  const double to_m = metres_per_unit(file.group("model").string_attribute("unit"), piv_h5.string());
  for (std::size_t k : {reference_image, image}) {
    if (k < 1 || k > names.size()) {
      throw InputError(fmt::format("{}: image {} does not exist (the file holds images 1 to {})", piv_h5.string(), k,
                                   names.size()));
    }
  }
  if (image == reference_image) throw InputError(fmt::format("PIV image {} is also the reference image", image));
  const Hdf5Group images = file.group("images");
  const Hdf5Group ref = images.group(fmt::format("{:06d}", reference_image));
  const Hdf5Group cur = images.group(fmt::format("{:06d}", image));
  const auto xr = ref.read_doubles("x_model"), zr = ref.read_doubles("z_model"), wr = ref.read_doubles("w_model");
  const auto wc = cur.read_doubles("w_model");
  const auto vr = ref.read_uint8s("valid"), vc = cur.read_uint8s("valid");
  const std::size_t n = wc.size();
  if (xr.size() != n || zr.size() != n || wr.size() != n || vr.size() != n || vc.size() != n) {
    throw InputError(fmt::format("{}: images {} and {} hold different subset counts", piv_h5.string(), reference_image,
                                 image));
  }
  ScatteredDisplacement out;
  const Hdf5Group grid = file.group("grid");
  const auto m = file.group("model").read_doubles("pixel_to_model");
  // Model length of one step: the scale of the transform's linear part (sqrt of |det|).
  const double det = m.size() == 9 ? std::abs(m[0] * m[4] - m[1] * m[3]) / (m[8] * m[8]) : 0.0;
  out.spacing = static_cast<double>(grid.int_attribute("step")) * std::sqrt(det) * to_m;
  for (std::size_t i = 0; i < n; ++i) {
    if (!vc[i] || (reference_image != 1 && !vr[i])) continue;
    if (!std::isfinite(xr[i]) || !std::isfinite(zr[i]) || !std::isfinite(wr[i]) || !std::isfinite(wc[i])) continue;
    out.position.push_back({xr[i] * to_m - origin.x, zr[i] * to_m - origin.z});
    out.w.push_back((wc[i] - wr[i]) * to_m);
  }
  if (out.position.empty()) {
    throw InputError(fmt::format("{}: no subset is valid in image {}{}", piv_h5.string(), image,
                                 reference_image != 1 ? fmt::format(" and image {}", reference_image) : ""));
  }
  return out;
}

long rendered_snapshot_index(const std::string& image_name) {
  const std::string file = std::filesystem::path(image_name).filename().string();
  std::size_t k = 0;
  while (k < file.size() && std::isdigit(static_cast<unsigned char>(file[k]))) ++k;
  if (k == 0 || k >= file.size() || file[k] != '_') return -1;
  if (file.size() < 6 || file.compare(file.size() - 6, 6, "mm.png") != 0) return -1;
  return std::stol(file.substr(0, k));
}

}  // namespace trapdem
