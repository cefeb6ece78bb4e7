#pragma once
// Total strain of every triangle: reference configuration to current, the displacement gradient
// taken over the reference geometry (small strain, Lagrangian), as in the paper's Figures 5 and 7.
#include <vector>

#include "analysis/plane_strain.hpp"
#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"

namespace trapdem {

// Strain of each triangle of `mesh` (node indices into positions/displacements), compression
// positive. Degenerate triangles give NaN; filter them first (filter_triangles).
std::vector<PlaneStrain> triangle_strains(const TriangleMesh& mesh, const std::vector<Point2>& positions,
                                          const std::vector<Point2>& displacements);
std::vector<PlaneStrain> total_strains(const TriangleMesh& mesh, const PointSet2& points);

// The invariants of a strain list, element by element.
std::vector<double> maximum_shear_strains(const std::vector<PlaneStrain>& strains);
std::vector<double> volumetric_strains(const std::vector<PlaneStrain>& strains);

}  // namespace trapdem
