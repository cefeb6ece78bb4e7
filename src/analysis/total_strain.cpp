#include "analysis/total_strain.hpp"

namespace trapdem {

std::vector<PlaneStrain> triangle_strains(const TriangleMesh& mesh, const std::vector<Point2>& positions,
                                          const std::vector<Point2>& displacements) {
  std::vector<PlaneStrain> strains(mesh.size());
  for (std::size_t t = 0; t < mesh.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const std::array<Point2, 3> node{positions[tri[0]], positions[tri[1]], positions[tri[2]]};
    const std::array<Point2, 3> disp{displacements[tri[0]], displacements[tri[1]], displacements[tri[2]]};
    strains[t] = small_strain(cst_displacement_gradient(node, disp));
  }
  return strains;
}

std::vector<PlaneStrain> total_strains(const TriangleMesh& mesh, const PointSet2& points) {
  return triangle_strains(mesh, points.position, points.displacement);
}

std::vector<double> maximum_shear_strains(const std::vector<PlaneStrain>& strains) {
  std::vector<double> out(strains.size());
  for (std::size_t t = 0; t < strains.size(); ++t) out[t] = maximum_shear_strain(strains[t]);
  return out;
}

std::vector<double> volumetric_strains(const std::vector<PlaneStrain>& strains) {
  std::vector<double> out(strains.size());
  for (std::size_t t = 0; t < strains.size(); ++t) out[t] = volumetric_strain(strains[t]);
  return out;
}

}  // namespace trapdem
