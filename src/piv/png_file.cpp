#include "piv/png_file.hpp"

#include <fstream>
#include <vector>

#include <opencv2/imgcodecs.hpp>

#include "core/errors.hpp"
#include "io/atomic_file.hpp"

namespace trapdem {

void write_png_atomically(const std::filesystem::path& path, const cv::Mat& image) {
  write_atomically(path, [&](const std::filesystem::path& tmp) {
    std::vector<uchar> buffer;
    if (!cv::imencode(".png", image, buffer)) throw FileError(path.string() + ": cannot encode PNG");
    std::ofstream f(tmp, std::ios::binary);
    f.write(reinterpret_cast<const char*>(buffer.data()), static_cast<std::streamsize>(buffer.size()));
    if (!f) throw FileError(tmp.string() + ": write failed");
  });
}

}  // namespace trapdem
