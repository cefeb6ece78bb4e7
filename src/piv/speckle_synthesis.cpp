#include "piv/speckle_synthesis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

// The working image of a render is one double per pixel: at most 1 GiB (134 M px, e.g. 11 585 x
// 11 585), estimated before anything is allocated instead of ending in std::bad_alloc.
constexpr double kMaxWorkingBytes = 1024.0 * 1024.0 * 1024.0;

void check_settings(const SpeckleSettings& s) {
  if (s.width <= 0 || s.height <= 0) throw InputError("speckle synthesis: the image size must be positive");
  const double bytes = double(s.width) * double(s.height) * double(sizeof(double));
  if (bytes > kMaxWorkingBytes)
    throw InputError(fmt::format("speckle synthesis: an image of {} x {} px needs {:.3g} bytes of working memory; "
                                 "expected at most {:.0f} GiB ({:.3g} px)", s.width, s.height, bytes,
                                 kMaxWorkingBytes / (1024.0 * 1024.0 * 1024.0), kMaxWorkingBytes / sizeof(double)));
  if (!(s.speckle_radius > 0.0) || !std::isfinite(s.speckle_radius))
    throw InputError("speckle synthesis: the speckle radius must be positive");
  if (!(s.noise_std >= 0.0) || !std::isfinite(s.noise_std))
    throw InputError(fmt::format("speckle synthesis: noise {} grey levels: expected a finite number >= 0", s.noise_std));
  for (const double v : {s.coverage, s.margin, s.background, s.foreground})
    if (!std::isfinite(v)) throw InputError("speckle synthesis: coverage, margin and grey levels must be finite numbers");
}

}  // namespace

std::vector<Speckle> make_speckle_pattern(const SpeckleSettings& s) {
  check_settings(s);
  if (s.bit_depth != 8 && s.bit_depth != 16) throw InputError("speckle synthesis: bit depth must be 8 or 16");
  const double x0 = -s.margin, x1 = s.width + s.margin, y0 = -s.margin, y1 = s.height + s.margin;
  const double area = (x1 - x0) * (y1 - y0);
  const auto count =
      static_cast<std::size_t>(std::llround(s.coverage * area / (std::numbers::pi * s.speckle_radius * s.speckle_radius)));
  std::mt19937_64 random(s.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Speckle> pattern(count);
  for (auto& sp : pattern) {
    sp.centre = {x0 + (x1 - x0) * unit(random), y0 + (y1 - y0) * unit(random)};
    sp.radius = s.speckle_radius * (0.75 + 0.5 * unit(random));
  }
  return pattern;
}

cv::Mat render_speckle_image(const std::vector<Speckle>& pattern, const DisplacementField& field,
                             const SpeckleSettings& s, std::uint64_t noise_seed) {
  check_settings(s);
  cv::Mat sum = cv::Mat::zeros(s.height, s.width, CV_64F);
  constexpr double h = 0.5;  // px, step of the central differences for grad u
  for (const Speckle& sp : pattern) {
    const cv::Point2d X = sp.centre;
    const cv::Point2d centre = X + field(X);
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y))
      throw InputError(fmt::format("speckle synthesis: the displacement field is not finite at ({:.1f}, {:.1f}) px "
                                   "(check the magnitude)", X.x, X.y));
    // F = I + grad u by central differences; (F F^T)^-1 shapes the deformed Gaussian.
    const cv::Point2d du_dx = (field(X + cv::Point2d(h, 0)) - field(X - cv::Point2d(h, 0))) * (0.5 / h);
    const cv::Point2d du_dy = (field(X + cv::Point2d(0, h)) - field(X - cv::Point2d(0, h))) * (0.5 / h);
    const double F11 = 1.0 + du_dx.x, F12 = du_dy.x, F21 = du_dx.y, F22 = 1.0 + du_dy.y;
    const double det = F11 * F22 - F12 * F21;
    // G = F^-1; (F F^T)^-1 = G^T G.
    const double G11 = F22 / det, G12 = -F12 / det, G21 = -F21 / det, G22 = F11 / det;
    const double A = G11 * G11 + G21 * G21, B = G11 * G12 + G21 * G22, C = G12 * G12 + G22 * G22;
    const double inv_two_var = 0.5 / (sp.radius * sp.radius);
    const double reach = 6.0 * sp.radius * std::max({std::abs(F11) + std::abs(F12), std::abs(F21) + std::abs(F22), 1.0});
    const int c0 = std::max(0, static_cast<int>(std::floor(centre.x - reach)));
    const int c1 = std::min(s.width - 1, static_cast<int>(std::ceil(centre.x + reach)));
    const int r0 = std::max(0, static_cast<int>(std::floor(centre.y - reach)));
    const int r1 = std::min(s.height - 1, static_cast<int>(std::ceil(centre.y + reach)));
    for (int r = r0; r <= r1; ++r) {
      double* row = sum.ptr<double>(r);
      const double dy = r - centre.y;
      for (int c = c0; c <= c1; ++c) {
        const double dx = c - centre.x;
        const double exponent = (A * dx * dx + 2.0 * B * dx * dy + C * dy * dy) * inv_two_var;
        if (exponent < 18.0) row[c] += std::exp(-exponent);  // exp(-18) = 1.5e-8: negligible
      }
    }
  }
  std::mt19937_64 random(noise_seed);
  std::normal_distribution<double> noise(0.0, s.noise_std > 0.0 ? s.noise_std : 1.0);
  const double full_scale = s.bit_depth == 16 ? 65535.0 : 255.0;
  const double per_grey_level = s.bit_depth == 16 ? 257.0 : 1.0;
  cv::Mat out(s.height, s.width, s.bit_depth == 16 ? CV_16U : CV_8U);
  for (int r = 0; r < s.height; ++r) {
    const double* row = sum.ptr<double>(r);
    for (int c = 0; c < s.width; ++c) {
      double grey = s.background + (s.foreground - s.background) * (1.0 - std::exp(-row[c]));
      if (s.noise_std > 0.0) grey += noise(random);
      const double level = std::clamp(std::round(grey * per_grey_level), 0.0, full_scale);
      if (s.bit_depth == 16) out.at<std::uint16_t>(r, c) = static_cast<std::uint16_t>(level);
      else out.at<std::uint8_t>(r, c) = static_cast<std::uint8_t>(level);
    }
  }
  return out;
}

std::vector<cv::Mat> synthesize_speckle_sequence(const SpeckleSettings& settings,
                                                 const std::vector<DisplacementField>& fields) {
  const std::vector<Speckle> pattern = make_speckle_pattern(settings);
  std::vector<cv::Mat> images;
  images.reserve(fields.size() + 1);
  images.push_back(render_speckle_image(pattern, rigid_shift(0.0, 0.0), settings, settings.seed));
  for (std::size_t k = 0; k < fields.size(); ++k)
    images.push_back(render_speckle_image(pattern, fields[k], settings, settings.seed + k + 1));
  return images;
}

}  // namespace trapdem
