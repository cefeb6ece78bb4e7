#include "piv/reference_subset.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "piv/subset_grid.hpp"

namespace trapdem {

namespace {

// In-place inverse of a symmetric positive-definite 6 x 6 matrix by Gauss-Jordan elimination with
// partial pivoting; false if it is (numerically) singular.
bool invert6(std::array<double, 36> m, std::array<double, 36>& inverse) {
  std::array<double, 36> inv{};
  for (int i = 0; i < 6; ++i) inv[i * 6 + i] = 1.0;
  double scale = 0.0;
  for (int i = 0; i < 6; ++i) scale = std::max(scale, std::abs(m[i * 6 + i]));
  if (!(scale > 0.0)) return false;
  for (int col = 0; col < 6; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 6; ++r)
      if (std::abs(m[r * 6 + col]) > std::abs(m[pivot * 6 + col])) pivot = r;
    if (std::abs(m[pivot * 6 + col]) < 1e-12 * scale) return false;
    if (pivot != col)
      for (int k = 0; k < 6; ++k) {
        std::swap(m[col * 6 + k], m[pivot * 6 + k]);
        std::swap(inv[col * 6 + k], inv[pivot * 6 + k]);
      }
    const double d = 1.0 / m[col * 6 + col];
    for (int k = 0; k < 6; ++k) {
      m[col * 6 + k] *= d;
      inv[col * 6 + k] *= d;
    }
    for (int r = 0; r < 6; ++r) {
      if (r == col) continue;
      const double factor = m[r * 6 + col];
      if (factor == 0.0) continue;
      for (int k = 0; k < 6; ++k) {
        m[r * 6 + k] -= factor * m[col * 6 + k];
        inv[r * 6 + k] -= factor * inv[col * 6 + k];
      }
    }
  }
  inverse = inv;
  return true;
}

}  // namespace

std::optional<ReferenceSubset> make_reference_subset(const BSplineImage& reference, cv::Point2d centre, int size) {
  const double first = subset_first_offset(size);
  if (!inside_interpolation_band(reference, centre.x + first, centre.y + first) ||
      !inside_interpolation_band(reference, centre.x - first, centre.y - first))
    return std::nullopt;

  ReferenceSubset s;
  s.centre = centre;
  s.size = size;
  const std::size_t n = static_cast<std::size_t>(size) * size;
  std::vector<double> f(n);
  s.steepest_descent.resize(n);
  double mean = 0.0;
  std::size_t k = 0;
  for (int j = 0; j < size; ++j) {
    const double dy = first + j;
    for (int i = 0; i < size; ++i, ++k) {
      const double dx = first + i;
      const ValueAndGradient g = interpolate_with_gradient(reference, centre.x + dx, centre.y + dy);
      f[k] = g.value;
      mean += g.value;
      // grad f . dW/dp for p = (u, v, u_x, v_x, u_y, v_y): dW/dp = [[1, 0, dx, 0, dy, 0], [0, 1, 0, dx, 0, dy]].
      s.steepest_descent[k] = {g.dx, g.dy, g.dx * dx, g.dy * dx, g.dx * dy, g.dy * dy};
      s.sum_squared_gradient_x += g.dx * g.dx;
      s.sum_squared_gradient_y += g.dy * g.dy;
    }
  }
  mean /= static_cast<double>(n);
  s.f_centred.resize(n);
  double sum_sq = 0.0;
  for (std::size_t q = 0; q < n; ++q) {
    s.f_centred[q] = f[q] - mean;
    sum_sq += s.f_centred[q] * s.f_centred[q];
  }
  s.f_norm = std::sqrt(sum_sq);
  s.intensity_std = std::sqrt(sum_sq / static_cast<double>(n));

  std::array<double, 36> hessian{};
  for (const auto& sd : s.steepest_descent)
    for (int a = 0; a < 6; ++a)
      for (int b = a; b < 6; ++b) hessian[a * 6 + b] += sd[a] * sd[b];
  for (int a = 0; a < 6; ++a)
    for (int b = 0; b < a; ++b) hessian[a * 6 + b] = hessian[b * 6 + a];
  if (!(s.f_norm > 0.0) || !invert6(hessian, s.inverse_hessian)) return std::nullopt;
  return s;
}

}  // namespace trapdem
