#include "plot/text.hpp"

#include <numbers>

namespace trapdem::plot {

namespace {

void select_font(cairo_t* cr, const TextStyle& style) {
  cairo_select_font_face(cr, "DejaVu Sans", CAIRO_FONT_SLANT_NORMAL,
                         style.bold ? CAIRO_FONT_WEIGHT_BOLD : CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, style.size);
}

// Offset of the text origin from the anchor, in the text's own (rotated) frame.
void origin_offset(cairo_t* cr, const std::string& text, const TextStyle& style, double& dx, double& dy,
                   double& width, double& ascent, double& descent) {
  cairo_text_extents_t te;
  cairo_font_extents_t fe;
  cairo_text_extents(cr, text.c_str(), &te);
  cairo_font_extents(cr, &fe);
  width = te.x_advance;
  ascent = fe.ascent;
  descent = fe.descent;
  dx = style.h == HAlign::left ? 0.0 : style.h == HAlign::centre ? -0.5 * width : -width;
  switch (style.v) {
    case VAlign::top: dy = ascent; break;
    case VAlign::middle: dy = 0.5 * (ascent - descent); break;
    case VAlign::baseline: dy = 0.0; break;
    case VAlign::bottom: dy = -descent; break;
  }
}

}  // namespace

Rect text_box(cairo_t* cr, const std::string& text, const TextStyle& style, double x, double y) {
  cairo_save(cr);
  select_font(cr, style);
  double dx = 0.0, dy = 0.0, width = 0.0, ascent = 0.0, descent = 0.0;
  origin_offset(cr, text, style, dx, dy, width, ascent, descent);
  cairo_restore(cr);
  return {x + dx, y + dy - ascent, width, ascent + descent};
}

Rect draw_text(cairo_t* cr, const std::string& text, double x, double y, const TextStyle& style) {
  cairo_save(cr);
  select_font(cr, style);
  double dx = 0.0, dy = 0.0, width = 0.0, ascent = 0.0, descent = 0.0;
  origin_offset(cr, text, style, dx, dy, width, ascent, descent);
  cairo_translate(cr, x, y);
  cairo_rotate(cr, -style.angle_deg * std::numbers::pi / 180.0);
  cairo_move_to(cr, dx, dy);
  set_colour(cr, style.colour);
  cairo_show_text(cr, text.c_str());
  cairo_new_path(cr);
  cairo_restore(cr);
  return {x + dx, y + dy - ascent, width, ascent + descent};
}

Rect draw_text_on_box(cairo_t* cr, const std::string& text, double x, double y, const TextStyle& style,
                      Rgb background, double padding) {
  TextStyle centred = style;
  centred.h = HAlign::centre;
  centred.v = VAlign::middle;
  centred.angle_deg = 0.0;
  Rect box = text_box(cr, text, centred, x, y);
  box = {box.x - padding, box.y - padding, box.w + 2 * padding, box.h + 2 * padding};
  cairo_save(cr);
  set_colour(cr, background);
  cairo_rectangle(cr, box.x, box.y, box.w, box.h);
  cairo_fill(cr);
  cairo_restore(cr);
  draw_text(cr, text, x, y, centred);
  return box;
}

void draw_title(cairo_t* cr, double x, double y, const std::string& title, const std::string& subtitle, double size) {
  draw_text(cr, title, x, y, TextStyle{.size = size, .bold = true, .v = VAlign::top});
  // The subtitle's lines are separated by '\n'.
  double line_y = y + 1.45 * size;
  std::size_t start = 0;
  while (start < subtitle.size()) {
    std::size_t end = subtitle.find('\n', start);
    if (end == std::string::npos) end = subtitle.size();
    draw_text(cr, subtitle.substr(start, end - start), x, line_y,
              TextStyle{.size = 0.75 * size, .colour = {0.3, 0.3, 0.3}, .v = VAlign::top});
    line_y += 1.2 * size;
    start = end + 1;
  }
}

}  // namespace trapdem::plot
