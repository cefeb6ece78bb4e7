// Pixel to model coordinates (scale, affine and projective control-point fits with residuals) and
// the displacements.csv writer.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "core/errors.hpp"
#include "piv/displacement_csv.hpp"
#include "piv/pixel_to_model.hpp"
#include "piv/run_piv.hpp"
#include "piv/speckle_synthesis.hpp"

namespace trapdem {
namespace {

TEST(PixelToModel, ScaleFlipsTheImageAxisSoZIsUp) {
  const PixelToModel t = scale_transform(0.5, {100.0, 200.0});
  const cv::Point2d a = to_model(t, {100.0, 200.0});
  const cv::Point2d b = to_model(t, {110.0, 180.0});
  EXPECT_NEAR(a.x, 0.0, 1e-12);
  EXPECT_NEAR(a.y, 0.0, 1e-12);
  EXPECT_NEAR(b.x, 5.0, 1e-12);   // 10 px right = 5 mm
  EXPECT_NEAR(b.y, 10.0, 1e-12);  // 20 px up the image = 10 mm up
  EXPECT_THROW(scale_transform(0.0), InputError);
}

std::vector<ControlPoint> points_through(const cv::Matx33d& m, const std::vector<cv::Point2d>& pixels) {
  std::vector<ControlPoint> out;
  for (const auto& p : pixels) {
    const cv::Vec3d h = m * cv::Vec3d(p.x, p.y, 1.0);
    out.push_back({p, {h[0] / h[2], h[1] / h[2]}});
  }
  return out;
}

TEST(PixelToModel, AffineFitRecoversTheTransformAndReportsResiduals) {
  const cv::Matx33d truth(0.21, 0.01, -30.0, -0.005, -0.2, 400.0, 0, 0, 1);
  auto points = points_through(truth, {{10, 20}, {3000, 40}, {2900, 2800}, {50, 2950}, {1500, 1500}});
  ControlPointFit fit = fit_control_points(points, ControlPointFitKind::affine);
  EXPECT_LT(fit.max_residual, 1e-9);
  const cv::Point2d p = to_model(fit.transform, {1234.0, 567.0});
  EXPECT_NEAR(p.x, 0.21 * 1234 + 0.01 * 567 - 30.0, 1e-8);
  // A point 0.3 mm off shows in the residuals.
  points[4].model.x += 0.3;
  fit = fit_control_points(points, ControlPointFitKind::affine);
  ASSERT_EQ(fit.residual.size(), 5u);
  EXPECT_GT(fit.max_residual, 0.1);
  EXPECT_GT(fit.rms_residual, 0.05);
}

TEST(PixelToModel, ProjectiveFitRecoversAPerspective) {
  const cv::Matx33d truth(0.2, 0.01, -30.0, -0.005, -0.2, 400.0, 1e-5, -2e-5, 1.0);
  const auto points = points_through(truth, {{10, 20}, {3000, 40}, {2900, 2800}, {50, 2950}, {1500, 1400}, {700, 2000}});
  const ControlPointFit fit = fit_control_points(points, ControlPointFitKind::projective);
  EXPECT_LT(fit.max_residual, 1e-4);  // model units of ~400: relative 2.5e-7
  const cv::Vec3d h = truth * cv::Vec3d(2000, 1000, 1);
  const cv::Point2d p = to_model(fit.transform, {2000.0, 1000.0});
  EXPECT_NEAR(p.x, h[0] / h[2], 1e-4);
  EXPECT_NEAR(p.y, h[1] / h[2], 1e-4);
  // The affine fit of the same points leaves residuals: the perspective is real.
  EXPECT_GT(fit_control_points(points, ControlPointFitKind::affine).max_residual, 0.1);
}

TEST(PixelToModel, TooFewOrCollinearPointsAreRefused) {
  const cv::Matx33d truth(0.2, 0, 0, 0, -0.2, 0, 0, 0, 1);
  EXPECT_THROW(fit_control_points(points_through(truth, {{0, 0}, {10, 0}}), ControlPointFitKind::affine), InputError);
  EXPECT_THROW(fit_control_points(points_through(truth, {{0, 0}, {10, 0}, {20, 5}}), ControlPointFitKind::projective),
               InputError);
  EXPECT_THROW(fit_control_points(points_through(truth, {{0, 0}, {10, 10}, {20, 20}}), ControlPointFitKind::affine),
               InputError);
}

TEST(DisplacementCsv, HeaderAndOneRowPerImageAndSubset) {
  SpeckleSettings s;
  s.width = 96;
  s.height = 96;
  const auto images = synthesize_speckle_sequence(s, {rigid_shift(0.25, -0.5)});
  PivSettings settings;
  settings.roi = RegionOfInterest{8, 8, 88, 88};
  const PivResult r = run_piv(images, settings);
  std::ostringstream out;
  write_displacements_csv(r, out);
  std::istringstream in(out.str());
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "image,x_px,y_px,u_px,v_px,zncc,valid");
  std::size_t rows = 0;
  while (std::getline(in, line)) ++rows;
  EXPECT_EQ(rows, 2 * r.grid.size());
  // The first subset: centre (8 + 15.5, 8 + 15.5), image 2 shifted by (0.25, -0.5).
  std::istringstream again(out.str());
  std::getline(again, line);
  for (std::size_t i = 0; i < r.grid.size(); ++i) std::getline(again, line);
  std::getline(again, line);
  EXPECT_EQ(line.substr(0, 12), "2,23.5,23.5,");
  EXPECT_EQ(line.back(), '1');
}

}  // namespace
}  // namespace trapdem
