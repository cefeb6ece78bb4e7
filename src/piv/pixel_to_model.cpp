#include "piv/pixel_to_model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <opencv2/calib3d.hpp>

#include "core/errors.hpp"

namespace trapdem {

PixelToModel scale_transform(double mm_per_px, cv::Point2d origin) {
  if (!(mm_per_px > 0.0)) throw InputError("PIV scale: mm per px must be positive, got " + std::to_string(mm_per_px));
  PixelToModel t;
  t.matrix = cv::Matx33d(mm_per_px, 0.0, -mm_per_px * origin.x,  //
                         0.0, -mm_per_px, mm_per_px * origin.y,  //
                         0.0, 0.0, 1.0);
  return t;
}

cv::Point2d to_model(const PixelToModel& t, cv::Point2d p) {
  const cv::Vec3d h = t.matrix * cv::Vec3d(p.x, p.y, 1.0);
  return {h[0] / h[2], h[1] / h[2]};
}

namespace {

// Least squares for X = a x + b y + c, Z = d x + e y + f over all points (cv::solve with SVD).
cv::Matx33d fit_affine(const std::vector<ControlPoint>& points) {
  const int n = static_cast<int>(points.size());
  cv::Mat A = cv::Mat::zeros(2 * n, 6, CV_64F), b(2 * n, 1, CV_64F);
  for (int i = 0; i < n; ++i) {
    const auto& p = points[i];
    A.at<double>(2 * i, 0) = p.pixel.x;
    A.at<double>(2 * i, 1) = p.pixel.y;
    A.at<double>(2 * i, 2) = 1.0;
    A.at<double>(2 * i + 1, 3) = p.pixel.x;
    A.at<double>(2 * i + 1, 4) = p.pixel.y;
    A.at<double>(2 * i + 1, 5) = 1.0;
    b.at<double>(2 * i) = p.model.x;
    b.at<double>(2 * i + 1) = p.model.y;
  }
  cv::Mat w;
  cv::SVD::compute(A, w);
  if (w.at<double>(5) <= 1e-9 * w.at<double>(0))
    throw InputError("PIV control points: they lie on a line; an affine fit needs three points not in line");
  cv::Mat x;
  cv::solve(A, b, x, cv::DECOMP_SVD);
  return cv::Matx33d(x.at<double>(0), x.at<double>(1), x.at<double>(2), x.at<double>(3), x.at<double>(4),
                     x.at<double>(5), 0.0, 0.0, 1.0);
}

}  // namespace

ControlPointFit fit_control_points(const std::vector<ControlPoint>& points, ControlPointFitKind kind) {
  const std::size_t needed = kind == ControlPointFitKind::affine ? 3 : 4;
  if (points.size() < needed)
    throw InputError("PIV control points: " + std::to_string(points.size()) + " given; the " +
                     (kind == ControlPointFitKind::affine ? "affine" : "projective") + " fit needs at least " +
                     std::to_string(needed));
  ControlPointFit fit;
  if (kind == ControlPointFitKind::affine) {
    fit.transform.matrix = fit_affine(points);
  } else {
    std::vector<cv::Point2d> src, dst;
    for (const auto& p : points) {
      src.push_back(p.pixel);
      dst.push_back(p.model);
    }
    cv::Mat H;
    try {
      H = cv::findHomography(src, dst, 0);  // method 0: least squares over all points
    } catch (const cv::Exception& e) {
      throw InputError(std::string("PIV control points: the projective fit failed (") + e.what() + ")");
    }
    if (H.empty())
      throw InputError("PIV control points: the projective fit failed (three or more points on a line?)");
    fit.transform.matrix = cv::Matx33d(H.ptr<double>());
  }
  double sum_sq = 0.0;
  for (const auto& p : points) {
    const double r = cv::norm(to_model(fit.transform, p.pixel) - p.model);
    fit.residual.push_back(r);
    sum_sq += r * r;
    fit.max_residual = std::max(fit.max_residual, r);
  }
  fit.rms_residual = std::sqrt(sum_sq / static_cast<double>(points.size()));
  return fit;
}

}  // namespace trapdem
