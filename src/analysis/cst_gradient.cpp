#include "analysis/cst_gradient.hpp"

#include <limits>

#include "analysis/triangle_mesh.hpp"

namespace trapdem {

DisplacementGradient cst_displacement_gradient(const std::array<Point2, 3>& n, const std::array<Point2, 3>& d) {
  // Constant strain triangle shape-function derivatives (formulas.md, "Strain from displacements").
  const double two_area = twice_signed_area(n[0], n[1], n[2]);
  if (two_area == 0.0) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan, nan};
  }
  const double b[3] = {n[1].z - n[2].z, n[2].z - n[0].z, n[0].z - n[1].z};
  const double c[3] = {n[2].x - n[1].x, n[0].x - n[2].x, n[1].x - n[0].x};
  DisplacementGradient g;
  for (int i = 0; i < 3; ++i) {
    g.du_dx += b[i] * d[i].x;
    g.du_dz += c[i] * d[i].x;
    g.dw_dx += b[i] * d[i].z;
    g.dw_dz += c[i] * d[i].z;
  }
  const double inv = 1.0 / two_area;
  g.du_dx *= inv;
  g.du_dz *= inv;
  g.dw_dx *= inv;
  g.dw_dz *= inv;
  return g;
}

}  // namespace trapdem
