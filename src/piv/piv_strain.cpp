#include "piv/piv_strain.hpp"

#include <cmath>
#include <stdexcept>

#include "analysis/delaunay.hpp"
#include "analysis/incremental_strain.hpp"
#include "analysis/total_strain.hpp"
#include "analysis/triangle_filter.hpp"
#include "core/errors.hpp"

namespace trapdem {

namespace {

// Subsets valid in every image of [first, last].
std::vector<std::size_t> valid_throughout(const PivResult& r, std::size_t first, std::size_t last) {
  if (last >= r.image_count())
    throw InputError("PIV strain: image " + std::to_string(last) + " asked for; the run has " +
                     std::to_string(r.image_count()) + " images");
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < r.grid.size(); ++i) {
    bool ok = true;
    for (std::size_t k = first; k <= last && ok; ++k) ok = r.image[k].subset[i].is_valid();
    if (ok) out.push_back(i);
  }
  return out;
}

cv::Point2d pixel_position(const PivResult& r, std::size_t image, std::size_t i) {
  const auto& m = r.image[image].subset[i];
  return r.grid.centre[i] + cv::Point2d(m.u, m.v);
}

Point2 model_point(const PixelToModel& t, cv::Point2d p) {
  const cv::Point2d m = to_model(t, p);
  return {m.x, m.y};
}

// Delaunay mesh of the nodes in image 1 pixels (x, -y: counter-clockwise with z up), filtered
// with the grid step as the length scale.
TriangleMesh mesh_over(const PivResult& r, const std::vector<std::size_t>& nodes, const PivStrainSettings& s) {
  std::vector<Point2> pixel_nodes;
  pixel_nodes.reserve(nodes.size());
  for (std::size_t i : nodes) pixel_nodes.push_back({r.grid.centre[i].x, -r.grid.centre[i].y});
  TriangleFilterSettings filter;
  filter.mean_diameter = static_cast<double>(r.grid.step);
  filter.max_edge_in_diameters = s.max_edge_in_steps;
  filter.min_angle_deg = s.min_angle_deg;
  return filter_triangles(delaunay_triangulation(pixel_nodes), pixel_nodes, filter).mesh;
}

PivStrainField field_over(const PivResult& r, const std::vector<std::size_t>& nodes, const PixelToModel& t,
                          const PivStrainSettings& s) {
  PivStrainField f;
  f.subset = nodes;
  f.mesh = mesh_over(r, nodes, s);
  for (std::size_t i : nodes) f.position.push_back(model_point(t, r.grid.centre[i]));
  return f;
}

void finish(PivStrainField& f) {
  f.max_shear = maximum_shear_strains(f.strain);
  f.volumetric = volumetric_strains(f.strain);
}

}  // namespace

PivStrainField piv_total_strain(const PivResult& r, std::size_t image, const PixelToModel& t,
                                const PivStrainSettings& s) {
  PivStrainField f = field_over(r, valid_throughout(r, image, image), t, s);
  for (std::size_t k = 0; k < f.subset.size(); ++k)
    f.displacement.push_back(model_point(t, pixel_position(r, image, f.subset[k])) - f.position[k]);
  f.strain = triangle_strains(f.mesh, f.position, f.displacement);
  finish(f);
  return f;
}

PivStrainField piv_incremental_strain(const PivResult& r, std::size_t image, const PixelToModel& t,
                                      const PivStrainSettings& s) {
  if (image == 0) throw InputError("PIV strain: the incremental strain needs an image after image 1");
  PivStrainField f = field_over(r, valid_throughout(r, image - 1, image), t, s);
  std::vector<Point2> previous, current;
  for (std::size_t i : f.subset) {
    previous.push_back(model_point(t, pixel_position(r, image - 1, i)));
    current.push_back(model_point(t, pixel_position(r, image, i)));
  }
  for (std::size_t k = 0; k < f.subset.size(); ++k) f.displacement.push_back(current[k] - previous[k]);
  f.strain = incremental_strains(f.mesh, previous, current);
  finish(f);
  return f;
}

PivStrainField piv_accumulated_strain(const PivResult& r, std::size_t image, const PixelToModel& t,
                                      const PivStrainSettings& s) {
  PivStrainField f = field_over(r, valid_throughout(r, 0, image), t, s);
  std::vector<std::vector<Point2>> configurations(image + 1);
  for (std::size_t k = 0; k <= image; ++k)
    for (std::size_t i : f.subset) configurations[k].push_back(model_point(t, pixel_position(r, k, i)));
  for (std::size_t k = 0; k < f.subset.size(); ++k)
    f.displacement.push_back(configurations[image][k] - f.position[k]);
  const AccumulatedStrain sum = accumulated_incremental_strain(f.mesh, configurations);
  f.strain = sum.strain;
  f.max_shear = sum.max_shear;
  f.volumetric = volumetric_strains(f.strain);
  return f;
}

}  // namespace trapdem
