#pragma once
// An image written as PNG atomically (io/atomic_file.hpp): a reader never finds half a file.
#include <filesystem>

#include <opencv2/core.hpp>

namespace trapdem {

// Throws FileError naming the path if it cannot be encoded or written.
void write_png_atomically(const std::filesystem::path& path, const cv::Mat& image);

}  // namespace trapdem
