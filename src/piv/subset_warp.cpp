#include "piv/subset_warp.hpp"

#include <cmath>

namespace trapdem {

bool compose_with_inverse(WarpParameters& p, const WarpParameters& dp) {
  // W(dp) = [[a, b, e], [c, d, f], [0, 0, 1]]; its inverse is [[A^-1, -A^-1 t], [0, 1]].
  const double a = 1.0 + dp.ux, b = dp.uy, c = dp.vx, d = 1.0 + dp.vy, e = dp.u, f = dp.v;
  const double det = a * d - b * c;
  if (!(std::abs(det) > 1e-12)) return false;
  const double ia = d / det, ib = -b / det, ic = -c / det, id = a / det;
  const double ie = -(ia * e + ib * f), iff = -(ic * e + id * f);
  // W(p) = [[P11, P12, P13], [P21, P22, P23], [0, 0, 1]].
  const double P11 = 1.0 + p.ux, P12 = p.uy, P13 = p.u, P21 = p.vx, P22 = 1.0 + p.vy, P23 = p.v;
  WarpParameters out;
  out.ux = P11 * ia + P12 * ic - 1.0;
  out.uy = P11 * ib + P12 * id;
  out.u = P11 * ie + P12 * iff + P13;
  out.vx = P21 * ia + P22 * ic;
  out.vy = P21 * ib + P22 * id - 1.0;
  out.v = P21 * ie + P22 * iff + P23;
  p = out;
  return true;
}

double update_norm(const WarpParameters& dp, double half_subset) {
  const double h = half_subset;
  return std::sqrt(dp.u * dp.u + dp.v * dp.v + h * h * (dp.ux * dp.ux + dp.vx * dp.vx + dp.uy * dp.uy +
                                                          dp.vy * dp.vy));
}

WarpParameters shifted_warp(const WarpParameters& p, double dx, double dy) {
  WarpParameters q = p;
  q.u = p.u + p.ux * dx + p.uy * dy;
  q.v = p.v + p.vx * dx + p.vy * dy;
  return q;
}

}  // namespace trapdem
