#pragma once
// The displacement gradient of a constant strain triangle (CST): displacements vary linearly
// between the three nodes, so the gradient is one constant per triangle.
#include <array>

#include "analysis/point_set.hpp"

namespace trapdem {

struct DisplacementGradient {
  double du_dx = 0.0;  // u: displacement along x (width)
  double du_dz = 0.0;
  double dw_dx = 0.0;  // w: displacement along z (height, up positive)
  double dw_dz = 0.0;
};

// Gradient of the linear interpolant through three nodes (any orientation) with displacements
// (u_i, w_i); see docs/analysis.md and shared/reference/formulas.md:
//   2A = (x2 - x1)(z3 - z1) - (x3 - x1)(z2 - z1)
//   b = (z2 - z3, z3 - z1, z1 - z2),  c = (x3 - x2, x1 - x3, x2 - x1)
//   du/dx = sum b_i u_i / 2A,  du/dz = sum c_i u_i / 2A  (and the same for w).
// A degenerate triangle (2A = 0) gives NaN components.
DisplacementGradient cst_displacement_gradient(const std::array<Point2, 3>& node,
                                               const std::array<Point2, 3>& displacement);

}  // namespace trapdem
