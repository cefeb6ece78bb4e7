#include "piv/icgn.hpp"

#include <cmath>
#include <vector>

#include "piv/subset_grid.hpp"

namespace trapdem {

IcgnResult refine_subset(const ReferenceSubset& reference, const BSplineImage& current, const WarpParameters& start,
                         const IcgnSettings& settings) {
  const int L = reference.size;
  const std::size_t n = static_cast<std::size_t>(L) * L;
  const double first = subset_first_offset(L);
  const double half_subset = 0.5 * L;
  std::vector<double> g(n);

  IcgnResult out;
  out.p = start;
  for (int iteration = 0;; ++iteration) {
    // Warped intensities g(W(x; p)) of the current image.
    const WarpParameters& p = out.p;
    double g_mean = 0.0;
    std::size_t k = 0;
    for (int j = 0; j < L; ++j) {
      const double dy = first + j;
      // Along a subset row the warped point moves by (1 + u_x, v_x) per pixel.
      double x = reference.centre.x + dy * p.uy + first * (1.0 + p.ux) + p.u;
      double y = reference.centre.y + dy * (1.0 + p.vy) + first * p.vx + p.v;
      for (int i = 0; i < L; ++i, ++k) {
        if (!inside_interpolation_band(current, x, y)) {
          out.outcome = IcgnOutcome::left_image;
          return out;
        }
        g[k] = interpolate(current, x, y);
        g_mean += g[k];
        x += 1.0 + p.ux;
        y += p.vx;
      }
    }
    g_mean /= static_cast<double>(n);
    double g_sum_sq = 0.0;
    for (std::size_t q = 0; q < n; ++q) {
      g[q] -= g_mean;
      g_sum_sq += g[q] * g[q];
    }
    const double g_norm = std::sqrt(g_sum_sq);
    if (!(g_norm > 0.0)) {
      out.outcome = IcgnOutcome::flat_target;
      return out;
    }

    // Residual f - f_mean - (df/dg)(g - g_mean), its ZNSSD and the right-hand side.
    const double ratio = reference.f_norm / g_norm;
    double rhs[6] = {0, 0, 0, 0, 0, 0};
    double sum_sq_residual = 0.0;
    for (std::size_t q = 0; q < n; ++q) {
      const double r = reference.f_centred[q] - ratio * g[q];
      sum_sq_residual += r * r;
      const auto& sd = reference.steepest_descent[q];
      for (int a = 0; a < 6; ++a) rhs[a] += sd[a] * r;
    }
    out.znssd = sum_sq_residual / (reference.f_norm * reference.f_norm);
    out.zncc = 1.0 - 0.5 * out.znssd;
    if (iteration >= settings.max_iterations) {
      out.outcome = IcgnOutcome::iteration_cap;
      return out;
    }

    // dp = -H^-1 rhs.
    double d[6];
    for (int a = 0; a < 6; ++a) {
      double s = 0.0;
      for (int b = 0; b < 6; ++b) s += reference.inverse_hessian[a * 6 + b] * rhs[b];
      d[a] = -s;
    }
    const WarpParameters dp{d[0], d[1], d[2], d[3], d[4], d[5]};
    if (!compose_with_inverse(out.p, dp)) {
      out.outcome = IcgnOutcome::singular_update;
      return out;
    }
    out.iterations = iteration + 1;
    if (std::hypot(out.p.u - start.u, out.p.v - start.v) > settings.max_wander) {
      out.outcome = IcgnOutcome::wandered;
      return out;
    }
    if (update_norm(dp, half_subset) < settings.convergence_tolerance) {
      out.outcome = IcgnOutcome::converged;
      return out;
    }
  }
}

}  // namespace trapdem
