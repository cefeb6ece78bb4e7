#pragma once
// Text on a figure: one sans-serif face (DejaVu Sans where installed), placed by an anchor point
// and alignment, optionally rotated (axis labels), optionally on a white box (contour labels).
#include <cairo.h>

#include <string>
#include <vector>

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

// Type sizes (layout units) of the figures, for figures about kFigureWidth units wide: printed one
// journal column wide (85 mm) the smallest text (tick numbers, legends, colour bars, contour labels)
// is 7 pt (canvas.hpp's kMinFontFraction).
inline constexpr double kFigureWidth = 640.0;
inline constexpr double kFontSmall = 19.0;   // ticks, legend, colour bar, contour labels, subtitles
inline constexpr double kFontLabel = 20.0;   // axis titles
inline constexpr double kFontTitle = 22.0;   // figure titles, bold

// `text` broken at spaces into lines no wider than `max_width` (a word longer than that stays whole);
// '\n' always breaks.
std::vector<std::string> wrap_text(cairo_t* cr, const std::string& text, const TextStyle& style, double max_width);

// A figure's title (bold, `size`) with a grey subtitle (kFontSmall) below it, both wrapped to
// `max_width`; (x, y) is the title's top left. Returns the y just below the last line.
double draw_title(cairo_t* cr, double x, double y, const std::string& title, const std::string& subtitle, double size,
                  double max_width);
// The height draw_title takes, measured without drawing (to size a canvas before it exists).
double title_height(const std::string& title, const std::string& subtitle, double size, double max_width);
// The width of `text` in `style` (unrotated), and wrap_text, measured without a canvas.
double text_width(const std::string& text, const TextStyle& style);
std::vector<std::string> wrap_text(const std::string& text, const TextStyle& style, double max_width);

}  // namespace trapdem::plot
