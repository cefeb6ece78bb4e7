#include "piv/bspline_image.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace trapdem {

namespace {

// Pole of the cubic B-spline prefilter, z = sqrt(3) - 2; overall gain (1 - z)(1 - 1/z) = 6.
constexpr double kPole = -0.26794919243112270;  // sqrt(3) - 2
constexpr double kGain = 6.0;

// Number of terms of the truncated causal start: |z|^30 < 1e-17.
constexpr int kHorizon = 30;

// Weights w_k of the causal start c+(0) = sum_k w_k s(k) for mirror-symmetric boundaries
// (Unser 1999, Box 2; Thevenaz, Blu & Unser 2000): z^k truncated for long lines, the exact
// finite sum (the mirrored signal folded back) for lines shorter than the horizon.
std::vector<double> causal_start_weights(int count) {
  std::vector<double> w(count, 0.0);
  if (count > kHorizon) {
    double zk = 1.0;
    for (int k = 0; k < kHorizon; ++k, zk *= kPole) w[k] = zk;
    return w;
  }
  // c+(0) = [s(0) + z^(n-1) s(n-1) + sum_{k=1}^{n-2} (z^k + z^(2n-2-k)) s(k)] / (1 - z^(2n-2)).
  const int n = count;
  const double denominator = 1.0 - std::pow(kPole, 2 * n - 2);
  w[0] = 1.0 / denominator;
  w[n - 1] = std::pow(kPole, n - 1) / denominator;
  for (int k = 1; k < n - 1; ++k) w[k] = (std::pow(kPole, k) + std::pow(kPole, 2 * n - 2 - k)) / denominator;
  return w;
}

// Unser's causal / anti-causal recursion with mirror-symmetric boundaries, applied in place to
// `count` samples spaced `stride` apart (Unser 1999, Box 2).
void prefilter_line(double* s, int count, std::ptrdiff_t stride, const std::vector<double>& start) {
  for (int k = 0; k < count; ++k) s[k * stride] *= kGain;
  double sum = 0.0;
  for (int k = 0; k < count; ++k)
    if (start[k] != 0.0) sum += start[k] * s[k * stride];
  s[0] = sum;
  for (int k = 1; k < count; ++k) s[k * stride] += kPole * s[(k - 1) * stride];
  const double last = s[(count - 1) * stride];
  const double before_last = s[(count - 2) * stride];
  s[(count - 1) * stride] = (kPole / (kPole * kPole - 1.0)) * (last + kPole * before_last);
  for (int k = count - 2; k >= 0; --k) s[k * stride] = kPole * (s[(k + 1) * stride] - s[k * stride]);
}

// The same recursion down the columns, all columns at once (rows are contiguous, so this walks
// memory in order instead of striding through it once per column).
void prefilter_columns(std::vector<double>& c, int width, int height) {
  auto row = [&](int r) { return c.data() + static_cast<std::size_t>(r) * width; };
  for (double& v : c) v *= kGain;
  const std::vector<double> start = causal_start_weights(height);
  std::vector<double> sum(width, 0.0);
  for (int r = 0; r < height; ++r) {
    if (start[r] == 0.0) continue;
    const double* src = row(r);
    for (int x = 0; x < width; ++x) sum[x] += start[r] * src[x];
  }
  std::copy(sum.begin(), sum.end(), row(0));
  for (int r = 1; r < height; ++r) {
    double* cur = row(r);
    const double* prev = row(r - 1);
    for (int x = 0; x < width; ++x) cur[x] += kPole * prev[x];
  }
  double* last = row(height - 1);
  const double* before_last = row(height - 2);
  for (int x = 0; x < width; ++x) last[x] = (kPole / (kPole * kPole - 1.0)) * (last[x] + kPole * before_last[x]);
  for (int r = height - 2; r >= 0; --r) {
    double* cur = row(r);
    const double* next = row(r + 1);
    for (int x = 0; x < width; ++x) cur[x] = kPole * (next[x] - cur[x]);
  }
}

// Cubic B-spline weights of the coefficients at i-1, i, i+1, i+2 for t = x - i in [0, 1).
inline void spline_weights(double t, double w[4]) {
  const double t2 = t * t, t3 = t2 * t, one_minus = 1.0 - t;
  w[0] = one_minus * one_minus * one_minus / 6.0;
  w[1] = (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0;
  w[2] = (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0;
  w[3] = t3 / 6.0;
}

// Their derivatives with respect to x.
inline void spline_derivative_weights(double t, double d[4]) {
  const double t2 = t * t, one_minus = 1.0 - t;
  d[0] = -0.5 * one_minus * one_minus;
  d[1] = 1.5 * t2 - 2.0 * t;
  d[2] = -1.5 * t2 + t + 0.5;
  d[3] = 0.5 * t2;
}

}  // namespace

BSplineImage make_bspline_image(const cv::Mat& intensity) {
  if (intensity.type() != CV_64FC1) throw InputError("B-spline image: expected a one-channel CV_64F matrix");
  if (intensity.cols < 4 || intensity.rows < 4)
    throw InputError("B-spline image: the image must be at least 4 x 4 pixels");
  const int w = intensity.cols, h = intensity.rows;
  std::vector<double> c(static_cast<std::size_t>(w) * h);
  for (int r = 0; r < h; ++r) {
    const double* src = intensity.ptr<double>(r);
    std::copy(src, src + w, c.data() + static_cast<std::size_t>(r) * w);
  }
  const std::vector<double> start = causal_start_weights(w);
  for (int r = 0; r < h; ++r) prefilter_line(c.data() + static_cast<std::size_t>(r) * w, w, 1, start);
  prefilter_columns(c, w, h);

  // With whole-sample mirror boundaries the coefficients are mirror-symmetric too:
  // c(-k) = c(k), c(w - 1 + k) = c(w - 1 - k). The padded border lets the 4 x 4 support reach
  // past the edge, so every point of the image can be interpolated.
  constexpr int P = BSplineImage::kPad;
  auto mirror = [](int k, int n) { return k < 0 ? -k : (k >= n ? 2 * (n - 1) - k : k); };
  BSplineImage s;
  s.width = w;
  s.height = h;
  s.stride = w + 2 * P;
  s.coefficient.resize(static_cast<std::size_t>(s.stride) * (h + 2 * P));
  for (int r = -P; r < h + P; ++r) {
    const double* src = c.data() + static_cast<std::size_t>(mirror(r, h)) * w;
    double* dst = s.coefficient.data() + static_cast<std::size_t>(r + P) * s.stride;
    for (int x = -P; x < w + P; ++x) dst[x + P] = src[mirror(x, w)];
  }
  return s;
}

double interpolate(const BSplineImage& s, double x, double y) {
  const int ix = static_cast<int>(std::floor(x));
  const int iy = static_cast<int>(std::floor(y));
  double wx[4], wy[4];
  spline_weights(x - ix, wx);
  spline_weights(y - iy, wy);
  double value = 0.0;
  for (int j = 0; j < 4; ++j) {
    const double* row = s.at(ix - 1, iy - 1 + j);
    value += wy[j] * (wx[0] * row[0] + wx[1] * row[1] + wx[2] * row[2] + wx[3] * row[3]);
  }
  return value;
}

ValueAndGradient interpolate_with_gradient(const BSplineImage& s, double x, double y) {
  const int ix = static_cast<int>(std::floor(x));
  const int iy = static_cast<int>(std::floor(y));
  double wx[4], wy[4], dx[4], dy[4];
  spline_weights(x - ix, wx);
  spline_weights(y - iy, wy);
  spline_derivative_weights(x - ix, dx);
  spline_derivative_weights(y - iy, dy);
  ValueAndGradient out;
  for (int j = 0; j < 4; ++j) {
    const double* row = s.at(ix - 1, iy - 1 + j);
    const double along = wx[0] * row[0] + wx[1] * row[1] + wx[2] * row[2] + wx[3] * row[3];
    const double slope = dx[0] * row[0] + dx[1] * row[1] + dx[2] * row[2] + dx[3] * row[3];
    out.value += wy[j] * along;
    out.dx += wy[j] * slope;
    out.dy += dy[j] * along;
  }
  return out;
}

}  // namespace trapdem
