#pragma once
// A figure to draw on with cairo, written as PNG, SVG or PDF (figure_format.hpp: the path's
// extension picks it). Drawing goes to a cairo recording surface, replayed at write time onto the
// format's surface: the figure code draws once, in layout units, for every format. One unit is one
// point in SVG and PDF and kPngPixelsPerUnit pixels in a PNG. The page starts white. Files are
// written atomically (io/atomic_file.hpp), so a figure on disk is never half written.
//
// Legibility: a figure is meant to be readable when printed one journal column wide (85 mm), so
// text is at least kMinFontFraction of the figure's width (7 pt at 85 mm); text.hpp's sizes follow.
#include <cairo.h>

#include <filesystem>
#include <string>

#include "plot/colour_map.hpp"

namespace trapdem::plot {

inline constexpr double kPngPixelsPerUnit = 2.0;
inline constexpr double kMinFontFraction = 7.0 / (85.0 / 25.4 * 72.0);  // 7 pt over 85 mm (241 pt)

class Canvas {
 public:
  Canvas(int width, int height);  // layout units; throws std::runtime_error if cairo cannot allocate
  Canvas(const Canvas&) = delete;
  Canvas& operator=(const Canvas&) = delete;
  ~Canvas();

  cairo_t* cr() const { return cr_; }
  int width() const { return width_; }
  int height() const { return height_; }

  // The figure's title, kept in the SVG (<title>) and PDF (document title) as text.
  void set_title(std::string title) { title_ = std::move(title); }

  // Writes the figure in the format `path`'s extension names (InputError for another extension,
  // FileError naming the path if it cannot be written). A PNG is width x height x kPngPixelsPerUnit^2
  // pixels.
  void write(const std::filesystem::path& path) const;

 private:
  int width_, height_;
  std::string title_;
  cairo_surface_t* surface_ = nullptr;  // the recording
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
