#pragma once
// A figure drawn over a photograph (the PIV figures): a kFigureWidth wide canvas with the
// photograph under an equal-aspect plot frame, the title block above it, axes in the photograph's plot coordinates
// (model units z up, or pixels with the image's y axis flipped) and room for a colour bar on the
// right. The photograph is given as plain 8-bit grey pixels and a 3 x 3 homogeneous pixel -> plot
// matrix, so this module needs neither OpenCV nor the PIV module.
#include <cairo.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "plot/axes.hpp"
#include "plot/canvas.hpp"
#include "plot/text.hpp"

namespace trapdem::plot {

// An 8-bit grey image, rows top to bottom, `width` bytes a row.
struct Photograph {
  int width = 0, height = 0;  // px
  std::vector<std::uint8_t> grey;
};

// Image pixel (x right, y down) -> plot coordinates: (X w, Y w, w) = M (x, y, 1), row-major.
using PixelToPlot = std::array<double, 9>;

// Plot coordinates of an image pixel (the homogeneous division of PixelToPlot).
std::array<double, 2> pixel_to_plot(const PixelToPlot& m, double x, double y);

// Where a figure put its photograph: image pixel -> canvas (layout units; a PNG has
// kPngPixelsPerUnit pixels per unit), the affine part of the pixel -> plot transform.
struct PhotoPlacement {
  cairo_matrix_t pixel_to_device;
  std::array<double, 2> device_of_pixel(double x, double y) const;
};

class PhotoFigure {
 public:
  // The canvas for a photograph of width x height px: the frame spans the photograph's pixels
  // (edges at -0.5 and size - 0.5) in plot coordinates, the canvas height follows its aspect (the
  // frame at most 1.2 kFigureWidth high) and the title block (bold title, grey subtitle, wrapped),
  // drawn at once.
  PhotoFigure(int photo_width, int photo_height, const PixelToPlot& pixel_to_plot, const std::string& title,
              const std::string& subtitle);

  cairo_t* cr() const { return canvas_.cr(); }
  const PlotFrame& frame() const { return frame_; }

  // Canvas coordinates of an image pixel by the affine part of the pixel -> plot transform (a
  // projective transform is approximated by it for the background and the pixel-sized marks).
  std::array<double, 2> device_of_pixel(double x, double y) const;
  PhotoPlacement placement() const { return {pixel_to_device_}; }
  // Canvas units per image pixel (square root of the affine part's determinant).
  double device_per_pixel() const;

  // The photograph under the frame (black around it); `fade` paints white over it (0: none).
  void draw_photograph(const Photograph& photograph, double fade);
  // Frame, ticks and axis titles; `unit` "px" labels the y axis as image rows counted upward.
  void draw_axes(const std::string& unit);
  // The colour bar's strip right of the frame.
  Rect colour_bar_rect() const;
  void write(const std::filesystem::path& path) const { canvas_.write(path); }

 private:
  Canvas canvas_;
  PlotFrame frame_;
  cairo_matrix_t pixel_to_device_;  // image pixel -> canvas, affine
};

}  // namespace trapdem::plot
