#include "piv/grey_image.hpp"

#include <string>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/errors.hpp"

namespace trapdem {

GreyImage to_grey_image(const cv::Mat& image) {
  if (image.empty()) throw InputError("PIV image: the image is empty (0 x 0 pixels)");
  const int depth = image.depth();
  const int channels = image.channels();
  if (channels != 1 && channels != 3 && channels != 4)
    throw InputError("PIV image: " + std::to_string(channels) + " channels; expected 1 (grey), 3 or 4 (colour)");

  cv::Mat grey;
  if (channels == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  else if (channels == 4) cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
  else grey = image;

  GreyImage out;
  switch (depth) {
    case CV_8U:
      grey.convertTo(out.intensity, CV_64F);
      out.source_bit_depth = 8;
      break;
    case CV_16U:
      grey.convertTo(out.intensity, CV_64F, 1.0 / 257.0);  // 65535 -> 255
      out.source_bit_depth = 16;
      break;
    case CV_32F:
    case CV_64F:
      if (channels != 1) throw InputError("PIV image: floating-point images must have one channel");
      grey.convertTo(out.intensity, CV_64F);
      out.source_bit_depth = 16;  // treated as finely quantised
      break;
    default:
      throw InputError("PIV image: unsupported pixel depth (OpenCV depth code " + std::to_string(depth) +
                       "); expected 8-bit or 16-bit unsigned");
  }
  return out;
}

bool is_readable_image(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return false;
  try {
    return cv::haveImageReader(file.string());
  } catch (const cv::Exception&) {
    return false;
  }
}

GreyImage read_grey_image(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    throw InputError("PIV image '" + file.string() + "': no such file");
  cv::Mat raw;
  try {
    raw = cv::imread(file.string(), cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR);
  } catch (const cv::Exception& e) {
    throw InputError("PIV image '" + file.string() + "': OpenCV cannot decode it (" + e.what() + ")");
  }
  if (raw.empty())
    throw InputError("PIV image '" + file.string() + "': OpenCV cannot decode it (not an image, or a format it "
                     "does not read)");
  try {
    return to_grey_image(raw);
  } catch (const InputError& e) {
    throw InputError("PIV image '" + file.string() + "': " + e.what());
  }
}

}  // namespace trapdem
