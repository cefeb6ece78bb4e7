#pragma once
// An image ready for matching: single-precision intensities for OpenCV's template matching and
// the cubic B-spline coefficients for sub-pixel interpolation.
#include <opencv2/core.hpp>

#include "piv/bspline_image.hpp"
#include "piv/grey_image.hpp"

namespace trapdem {

struct PreparedImage {
  cv::Mat intensity32;  // CV_32F, 8-bit scale
  BSplineImage spline;

  int width() const { return spline.width; }
  int height() const { return spline.height; }
};

PreparedImage prepare_image(const GreyImage& image);

}  // namespace trapdem
