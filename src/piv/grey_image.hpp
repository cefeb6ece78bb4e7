#pragma once
// Photographs as the PIV sees them: one grey channel in double precision, intensities on the
// 8-bit scale (0..255) whatever the file's depth, so that the texture thresholds (intensity
// standard deviation, sum of squared gradients; Stanier et al. 2016, Comput. Geotech. 72) keep
// their 8-bit meaning for 16-bit photographs too.
#include <filesystem>

#include <opencv2/core.hpp>

namespace trapdem {

struct GreyImage {
  cv::Mat intensity;       // CV_64F, one channel, 0..255 (8-bit grey levels)
  int source_bit_depth = 8;  // 8 or 16: the depth of the file or matrix it came from

  int width() const { return intensity.cols; }
  int height() const { return intensity.rows; }
};

// Converts an 8-bit or 16-bit matrix with 1, 3 or 4 channels (colour in OpenCV's BGR(A) order,
// luma weights of cv::cvtColor) to a GreyImage; 16-bit values are divided by 257 (65535 -> 255).
// Floating-point one-channel matrices are taken as already on the 8-bit scale.
// Throws InputError for an empty matrix or another depth / channel count.
GreyImage to_grey_image(const cv::Mat& image);

// Reads any file OpenCV can decode, keeping 16-bit depth (cv::IMREAD_ANYDEPTH | IMREAD_ANYCOLOR).
// Throws InputError naming the file if it does not exist or cannot be decoded.
GreyImage read_grey_image(const std::filesystem::path& file);

// Whether OpenCV recognises the file's format from its signature (no full decode); lets a run
// report an unreadable file before spending time on the images before it.
bool is_readable_image(const std::filesystem::path& file);

}  // namespace trapdem
