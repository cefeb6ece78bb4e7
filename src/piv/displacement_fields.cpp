#include "piv/displacement_fields.hpp"

#include <cmath>
#include <numbers>
#include <utility>

namespace trapdem {

DisplacementField rigid_shift(double u, double v) {
  return [u, v](cv::Point2d) { return cv::Point2d(u, v); };
}

DisplacementField uniform_strain(double exx, double eyy, cv::Point2d origin) {
  return [=](cv::Point2d p) { return cv::Point2d(exx * (p.x - origin.x), eyy * (p.y - origin.y)); };
}

DisplacementField simple_shear(double gamma, cv::Point2d origin) {
  return [=](cv::Point2d p) { return cv::Point2d(gamma * (p.y - origin.y), 0.0); };
}

DisplacementField trapdoor_settlement(const TrapdoorSettlement& t) {
  const double lean = std::tan(t.band_angle_deg * std::numbers::pi / 180.0);
  const double scale = 4.0 / t.band_width;  // logistic(+-2) = 0.88 / 0.12 at +-band_width / 2
  return [=](cv::Point2d p) {
    const double height = t.base_y - p.y;  // px above the trapdoor
    const double left = t.centre_x - 0.5 * t.width - height * lean;
    const double right = t.centre_x + 0.5 * t.width + height * lean;
    const double inside_left = 1.0 / (1.0 + std::exp(-scale * (p.x - left)));
    const double inside_right = 1.0 / (1.0 + std::exp(-scale * (right - p.x)));
    return cv::Point2d(0.0, t.settlement * inside_left * inside_right);
  };
}

DisplacementField scaled(DisplacementField field, double factor) {
  return [field = std::move(field), factor](cv::Point2d p) { return factor * field(p); };
}

}  // namespace trapdem
