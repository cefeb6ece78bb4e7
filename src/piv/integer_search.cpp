#include "piv/integer_search.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "piv/subset_grid.hpp"

namespace trapdem {

IntegerMatch integer_pixel_search(const cv::Mat& reference, const cv::Mat& current, cv::Point2d centre,
                                  int subset_size, cv::Point2d predicted, int search_radius) {
  IntegerMatch out;
  const double first = subset_first_offset(subset_size);
  const int left = static_cast<int>(std::lround(centre.x + first));
  const int top = static_cast<int>(std::lround(centre.y + first));
  const cv::Rect template_rect(left, top, subset_size, subset_size);
  if ((template_rect & cv::Rect(0, 0, reference.cols, reference.rows)) != template_rect) return out;

  const int shift_x = static_cast<int>(std::lround(predicted.x));
  const int shift_y = static_cast<int>(std::lround(predicted.y));
  const cv::Rect wanted(left + shift_x - search_radius, top + shift_y - search_radius,
                        subset_size + 2 * search_radius, subset_size + 2 * search_radius);
  const cv::Rect window = wanted & cv::Rect(0, 0, current.cols, current.rows);
  if (window.width < subset_size || window.height < subset_size) return out;

  const cv::Mat templ = reference(template_rect);
  cv::Scalar mean, std_dev;
  cv::meanStdDev(templ, mean, std_dev);
  if (!(std_dev[0] > 0.0)) return out;

  cv::Mat score;
  cv::matchTemplate(current(window), templ, score, cv::TM_CCOEFF_NORMED);
  // A flat patch in the window gives NaN or inf; such positions cannot win.
  cv::patchNaNs(score, -2.0);
  double best = -2.0;
  cv::Point best_at;
  for (int r = 0; r < score.rows; ++r) {
    const float* row = score.ptr<float>(r);
    for (int c = 0; c < score.cols; ++c)
      if (row[c] > best && row[c] <= 1.0001f) {
        best = row[c];
        best_at = {c, r};
      }
  }
  if (best < -1.0) return out;
  out.found = true;
  out.du = window.x + best_at.x - left;
  out.dv = window.y + best_at.y - top;
  out.zncc = best;
  return out;
}

}  // namespace trapdem
