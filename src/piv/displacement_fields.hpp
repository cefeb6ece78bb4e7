#pragma once
// Prescribed displacement fields for synthetic speckle images and tests: a displacement (px) for
// every reference position (px; x right, y down, as in the images).
#include <functional>

#include <opencv2/core.hpp>

namespace trapdem {

using DisplacementField = std::function<cv::Point2d(cv::Point2d reference_position)>;

// u = (u, v) everywhere, px.
DisplacementField rigid_shift(double u, double v);

// Uniform normal strain about `origin`: u = e_xx (x - x0), v = e_yy (y - y0) (tension positive).
DisplacementField uniform_strain(double exx, double eyy, cv::Point2d origin);

// Simple shear about `origin`: u = gamma (y - y0), v = 0 (engineering shear gamma = du/dy).
DisplacementField simple_shear(double gamma, cv::Point2d origin);

// A trapdoor-like settlement: the soil above a trapdoor of `width` px centred at centre_x, whose
// top is at row base_y, moves down by `settlement` px (negative: heave, a trapdoor pushed up),
// bounded by two shear bands that start at the trapdoor edges and lean `band_angle_deg` from the
// vertical (positive: outward going up). Across a band the settlement changes smoothly from 12 %
// to 88 % over band_width px (a logistic profile); u = 0.
struct TrapdoorSettlement {
  double centre_x = 128.0;    // px
  double width = 96.0;        // px, B
  double base_y = 256.0;      // px, row of the trapdoor (soil above has y < base_y)
  double settlement = 4.0;    // px, down positive
  double band_angle_deg = 10.0;
  double band_width = 6.0;    // px
};
DisplacementField trapdoor_settlement(const TrapdoorSettlement& t);

// `field` multiplied by `factor` (for a sequence of growing displacements).
DisplacementField scaled(DisplacementField field, double factor);

}  // namespace trapdem
