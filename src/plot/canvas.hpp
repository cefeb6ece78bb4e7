#pragma once
// A raster image to draw on with cairo: owns the image surface and its drawing context, starts
// white, and writes itself as PNG atomically (io/atomic_file.hpp), so a figure on disk is never
// half written.
#include <cairo.h>

#include <filesystem>

#include "plot/colour_map.hpp"

namespace trapdem::plot {

class Canvas {
 public:
  Canvas(int width, int height);  // pixels; throws std::runtime_error if cairo cannot allocate
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;
  ~Canvas();

  cairo_t* cr() const { return cr_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // Throws FileError naming the path.
  void write_png(const std::filesystem::path& path) const;

 private:
  int width_, height_;
  cairo_surface_t* surface_ = nullptr;
  cairo_t* cr_ = nullptr;
};

void set_colour(cairo_t* cr, Rgb c, double alpha = 1.0);

// Pixel rectangle: left, top, width, height.
struct Rect {
  double x = 0.0, y = 0.0, w = 0.0, h = 0.0;
  double right() const { return x + w; }
  double bottom() const { return y + h; }
  bool overlaps(const Rect& o) const { return x < o.right() && o.x < right() && y < o.bottom() && o.y < bottom(); }
};

}  // namespace trapdem::plot
