#pragma once
// First-order subset shape function (Stanier et al. 2016, eq. for W; Pan 2009; formulas.md):
//   x' = x_c + dx + u + u_x dx + u_y dy
//   y' = y_c + dy + v + v_x dx + v_y dy
// for a subset point at offset (dx, dy) from the subset centre (x_c, y_c), px. u, v in px; the
// four gradients dimensionless. As a 3 x 3 matrix acting on (dx, dy, 1):
//   W(p) = [[1 + u_x, u_y, u], [v_x, 1 + v_y, v], [0, 0, 1]].
#include <array>

namespace trapdem {

struct WarpParameters {
  double u = 0.0;   // px, displacement of the subset centre along x
  double v = 0.0;   // px, along y (down)
  double ux = 0.0;  // du/dx
  double vx = 0.0;  // dv/dx
  double uy = 0.0;  // du/dy
  double vy = 0.0;  // dv/dy
};

// Offset of the warped point from the subset centre in the reference image: W(p) (dx, dy) minus
// nothing, i.e. (dx + u + u_x dx + u_y dy, dy + v + v_x dx + v_y dy), px.
inline std::array<double, 2> warp_offset(const WarpParameters& p, double dx, double dy) {
  return {dx + p.u + p.ux * dx + p.uy * dy, dy + p.v + p.vx * dx + p.vy * dy};
}

// The inverse-compositional update W(p) <- W(p) o W(dp)^-1 (Baker & Matthews 2004; Pan et al.
// 2013, Exp. Mech. 53: 1277-1289). Returns false (p unchanged) if W(dp) is singular.
bool compose_with_inverse(WarpParameters& p, const WarpParameters& dp);

// Size of an update for the convergence test: sqrt(du^2 + dv^2 + (h du_x)^2 + (h dv_x)^2 +
// (h du_y)^2 + (h dv_y)^2), the gradients scaled by the half subset size h (px), so every term is
// the largest displacement it causes at the subset edge (formulas.md; GeoPIV-RG).
double update_norm(const WarpParameters& dp, double half_subset);

// The warp of a neighbouring subset whose centre lies (dx, dy) px away, from this subset's
// warp: the displacement extrapolated by the gradients, the gradients kept (Pan 2009's seeding
// of reliability-guided DIC).
WarpParameters shifted_warp(const WarpParameters& p, double dx, double dy);

}  // namespace trapdem
