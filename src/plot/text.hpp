#pragma once
// Text on a figure: one sans-serif face (DejaVu Sans where installed), placed by an anchor point
// and alignment, optionally rotated (axis labels), optionally on a white box (contour labels).
#include <cairo.h>

#include <string>

#include "plot/canvas.hpp"

namespace trapdem::plot {

enum class HAlign { left, centre, right };
enum class VAlign { top, middle, baseline, bottom };

struct TextStyle {
  double size = 16.0;  // pixels
  bool bold = false;
  Rgb colour{0.1, 0.1, 0.1};
  double angle_deg = 0.0;  // counter-clockwise rotation about the anchor
  HAlign h = HAlign::left;
  VAlign v = VAlign::baseline;
};

// Width and height (ascent + descent) of `text` in pixels.
Rect text_box(cairo_t* cr, const std::string& text, const TextStyle& style, double x = 0.0, double y = 0.0);

// Draws `text` at (x, y); returns the (unrotated) box it occupies.
Rect draw_text(cairo_t* cr, const std::string& text, double x, double y, const TextStyle& style);

// Draws `text` centred at (x, y) on a filled rectangle (padding pixels around).
Rect draw_text_on_box(cairo_t* cr, const std::string& text, double x, double y, const TextStyle& style,
                      Rgb background = {1.0, 1.0, 1.0}, double padding = 2.0);

// A figure's title (bold) with a grey subtitle below it whose lines are separated by '\n';
// (x, y) is the title's top left, `size` the title's font size (px).
void draw_title(cairo_t* cr, double x, double y, const std::string& title, const std::string& subtitle, double size);

}  // namespace trapdem::plot
