#pragma once
// A PNG read back for the figure tests (through cairo, as the figures are written): size, each
// pixel as 0xRRGGBB, and the number of distinct colours.
#include <cairo.h>

#include <cstdint>
#include <filesystem>
#include <set>
#include <stdexcept>
#include <vector>

namespace trapdem::test {

struct PngImage {
  int width = 0, height = 0;       // 0 if the file could not be read
  std::vector<std::uint32_t> rgb;  // row-major, 0xRRGGBB

  // Throws std::out_of_range outside the image (a figure drawn in the wrong place).
  std::uint32_t at(int x, int y) const {
    if (x < 0 || x >= width || y < 0 || y >= height) throw std::out_of_range("pixel outside the image");
    return rgb[static_cast<std::size_t>(y) * width + x];
  }
  int red(int x, int y) const { return static_cast<int>(at(x, y) >> 16 & 0xff); }
  int green(int x, int y) const { return static_cast<int>(at(x, y) >> 8 & 0xff); }
  int blue(int x, int y) const { return static_cast<int>(at(x, y) & 0xff); }
  std::size_t colours() const { return std::set<std::uint32_t>(rgb.begin(), rgb.end()).size(); }
};

inline PngImage read_png(const std::filesystem::path& path) {
  cairo_surface_t* s = cairo_image_surface_create_from_png(path.c_str());
  PngImage image;
  if (cairo_surface_status(s) == CAIRO_STATUS_SUCCESS) {
    image.width = cairo_image_surface_get_width(s);
    image.height = cairo_image_surface_get_height(s);
    const int stride = cairo_image_surface_get_stride(s);
    const unsigned char* data = cairo_image_surface_get_data(s);
    for (int y = 0; y < image.height; ++y) {
      const auto* row = reinterpret_cast<const std::uint32_t*>(data + y * stride);
      for (int x = 0; x < image.width; ++x) image.rgb.push_back(row[x] & 0xffffff);
    }
  }
  cairo_surface_destroy(s);
  return image;
}

}  // namespace trapdem::test
