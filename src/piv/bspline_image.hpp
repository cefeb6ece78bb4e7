#pragma once
// Cubic B-spline interpolation of an image: the coefficients are computed once per image by the
// recursive prefilter of Unser, Aldroubi & Eden (1991, IEEE Trans. Signal Process. 39(2): 277-285;
// Unser 1999, IEEE Signal Process. Mag. 16(6): 22-38), so that the spline passes through every
// pixel value; it is then evaluated with 4 x 4 coefficients. Cubic B-spline interpolation is the
// "bicubic or better" of Stanier et al. (2016) and the choice of Ncorr (Blaber et al. 2015): its
// bias for sub-pixel shifts is several times smaller than Keys' cubic convolution.
#include <cstddef>
#include <vector>

#include <opencv2/core.hpp>

namespace trapdem {

struct BSplineImage {
  static constexpr int kPad = 2;  // coefficients mirrored this many px beyond each edge
  int width = 0;   // px, of the image
  int height = 0;  // px
  int stride = 0;  // width + 2 kPad
  std::vector<double> coefficient;  // (width + 2 kPad) * (height + 2 kPad), row by row

  // Coefficient of pixel (col, row), col in [-kPad, width + kPad).
  const double* at(int col, int row) const {
    return coefficient.data() + static_cast<std::ptrdiff_t>(row + kPad) * stride + (col + kPad);
  }
};

// Pixel (col, row) has its centre at x = col, y = row (x right, y down, px).
// Throws InputError for an image smaller than 4 x 4 pixels or not CV_64F one-channel.
BSplineImage make_bspline_image(const cv::Mat& intensity);

// The spline is evaluated inside the image, x in [0, width - 1] and y in [0, height - 1]
// (mirror-symmetric beyond, as the prefilter assumes); outside that the caller must not ask.
inline bool inside_interpolation_band(const BSplineImage& s, double x, double y) {
  return x >= 0.0 && y >= 0.0 && x <= s.width - 1.0 && y <= s.height - 1.0;
}

// Value of the spline at (x, y), px; (x, y) inside the interpolation band.
double interpolate(const BSplineImage& s, double x, double y);

struct ValueAndGradient {
  double value = 0.0;
  double dx = 0.0;  // d value / dx, grey levels per px
  double dy = 0.0;  // d value / dy
};

// Value and exact derivatives of the spline at (x, y); (x, y) inside the interpolation band.
ValueAndGradient interpolate_with_gradient(const BSplineImage& s, double x, double y);

}  // namespace trapdem
