#pragma once
// Fields on the triangle mesh resampled on a regular grid: a nodal field (e.g. vertical
// displacement) linearly inside each triangle, a per-triangle field (e.g. gamma_max) piecewise
// constant. Grid nodes outside every triangle of the mesh get NaN, so holes left by the triangle
// filter and the region outside the specimen stay blank in contour plots.
#include <vector>

#include "analysis/grid_field.hpp"
#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"

namespace trapdem {

// Linear (barycentric) interpolation of nodal_value (one per node) inside each triangle.
// Throws InputError if nodal_value and nodes differ in size.
GridField interpolate_nodal_field(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                                  const std::vector<double>& nodal_value, const GridSpec& grid);

// The value of the triangle containing each grid node (one value per triangle).
// Throws InputError if triangle_value and mesh differ in size.
GridField sample_triangle_field(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                                const std::vector<double>& triangle_value, const GridSpec& grid);

}  // namespace trapdem
