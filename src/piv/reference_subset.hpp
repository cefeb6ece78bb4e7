#pragma once
// Everything about a reference subset that inverse-compositional Gauss-Newton (IC-GN) needs and
// that does not change during the iterations (Pan et al. 2013, Exp. Mech. 53: 1277-1289;
// Stanier et al. 2016): the zero-mean intensities, their norm, the steepest-descent images
// grad f . dW/dp and the inverse of the constant Hessian H = sum (grad f . dW/dp)^T (grad f . dW/dp).
#include <array>
#include <optional>
#include <vector>

#include <opencv2/core.hpp>

#include "piv/bspline_image.hpp"

namespace trapdem {

struct ReferenceSubset {
  cv::Point2d centre;  // px, in the reference image
  int size = 0;        // px, L; points at offsets first + (0..L-1) along x and y
  std::vector<double> f_centred;  // f - mean(f), grey levels, L * L, row by row
  double f_norm = 0.0;            // sqrt(sum (f - mean f)^2), grey levels
  std::vector<std::array<double, 6>> steepest_descent;  // per point: (f_x, f_y, f_x dx, f_y dx, f_x dy, f_y dy)
  std::array<double, 36> inverse_hessian{};             // 6 x 6, row-major, order (u, v, u_x, v_x, u_y, v_y)
  double intensity_std = 0.0;        // grey levels (8-bit scale), population standard deviation
  double sum_squared_gradient_x = 0.0;  // sum f_x^2, (grey levels / px)^2
  double sum_squared_gradient_y = 0.0;  // sum f_y^2
};

// Samples the subset of side `size` centred at `centre` from the reference spline (exact pixel
// values where the points are whole pixels), with the spline's exact gradients. Returns nothing
// if part of the subset lies outside the image or the Hessian is singular (a flat subset).
std::optional<ReferenceSubset> make_reference_subset(const BSplineImage& reference, cv::Point2d centre, int size);

}  // namespace trapdem
