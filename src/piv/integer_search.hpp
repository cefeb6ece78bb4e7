#pragma once
// Integer-pixel start of a subset: the zero-normalised cross-correlation (ZNCC) of the reference
// subset with every position in a search window of the current image (OpenCV's matchTemplate with
// TM_CCOEFF_NORMED, which is the ZNCC), best position kept (Stanier et al. 2016; Pan 2009 seeds).
#include <opencv2/core.hpp>

namespace trapdem {

struct IntegerMatch {
  bool found = false;  // false if the template or window left the images, or the template is flat
  int du = 0;          // px, displacement of the best position along x
  int dv = 0;          // px, along y
  double zncc = -1.0;  // ZNCC at the best position
};

// `reference` and `current`: CV_32F one-channel images of the same size. The template is the
// L x L block of `reference` nearest to the subset centred at `centre`; positions within
// `search_radius` px (each axis) of `centre` + `predicted` are tried, clipped to the image.
IntegerMatch integer_pixel_search(const cv::Mat& reference, const cv::Mat& current, cv::Point2d centre,
                                  int subset_size, cv::Point2d predicted, int search_radius);

}  // namespace trapdem
