#pragma once
// From image pixels (x right, y down, px) to model coordinates (x across the model, z up, in the
// unit of the scale or control points, normally mm): a 3 x 3 homogeneous matrix, either a plain
// scale or a fit to control points (affine: least squares; projective: OpenCV's findHomography,
// least squares over all points). The residuals of the fit are returned so they can be printed.
#include <vector>

#include <opencv2/core.hpp>

namespace trapdem {

struct PixelToModel {
  cv::Matx33d matrix = cv::Matx33d::eye();  // (X w, Z w, w) = matrix (x, y, 1)
};

// X = mm_per_px (x - origin.x), Z = -mm_per_px (y - origin.y): the image's y axis flipped so z
// is up. Throws InputError if mm_per_px is not positive.
PixelToModel scale_transform(double mm_per_px, cv::Point2d origin = {0.0, 0.0});

cv::Point2d to_model(const PixelToModel& t, cv::Point2d pixel);

struct ControlPoint {
  cv::Point2d pixel;  // px, in image 1
  cv::Point2d model;  // model coordinates (x, z up), e.g. mm
};

enum class ControlPointFitKind { affine, projective };

struct ControlPointFit {
  PixelToModel transform;
  std::vector<double> residual;  // |to_model(pixel) - model| per point, model units
  double rms_residual = 0.0;
  double max_residual = 0.0;
};

// Affine needs at least 3 points not on a line, projective at least 4 (no three on a line).
// Throws InputError with fewer points or a degenerate configuration.
ControlPointFit fit_control_points(const std::vector<ControlPoint>& points, ControlPointFitKind kind);

}  // namespace trapdem
