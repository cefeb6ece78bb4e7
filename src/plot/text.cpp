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

namespace {

// A word that stays on the line of the word before it: a unit after its number ("3 mm"), and the
// two sides of an equals sign ("δ = 3 mm").
bool glued(const std::string& previous, const std::string& word) {
  static const char* const units[] = {"mm", "m", "px", "d", "kPa", "Pa", "s", "%", "=", "−", "-"};
  for (const char* u : units) {
    if (word == u) return true;
  }
  return !previous.empty() && previous.back() == '=';
}

}  // namespace

std::vector<std::string> wrap_text(cairo_t* cr, const std::string& text, const TextStyle& style, double max_width) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string paragraph = text.substr(start, end - start);
    // Words, with glued ones joined to the word before.
    std::vector<std::string> words;
    std::size_t word_start = 0;
    while (word_start < paragraph.size()) {
      std::size_t word_end = paragraph.find(' ', word_start);
      if (word_end == std::string::npos) word_end = paragraph.size();
      const std::string word = paragraph.substr(word_start, word_end - word_start);
      if (!words.empty() && glued(words.back(), word)) words.back() += " " + word;
      else words.push_back(word);
      word_start = word_end + 1;
    }
    std::string line;
    for (const std::string& word : words) {
      const std::string longer = line.empty() ? word : line + " " + word;
      if (!line.empty() && text_box(cr, longer, style).w > max_width) {
        lines.push_back(line);
        line = word;
      } else {
        line = longer;
      }
    }
    if (!line.empty() || paragraph.empty()) lines.push_back(line);
    start = end + 1;
  }
  return lines;
}

namespace {

// Lays the title block out; draws it when `draw` (else measures only). Returns the y below it.
double title_block(cairo_t* cr, double x, double y, const std::string& title, const std::string& subtitle,
                   double size, double max_width, bool draw) {
  const TextStyle heading{.size = size, .bold = true, .v = VAlign::top};
  const TextStyle sub{.size = kFontSmall, .colour = {0.3, 0.3, 0.3}, .v = VAlign::top};
  double line_y = y;
  for (const std::string& line : wrap_text(cr, title, heading, max_width)) {
    if (draw) draw_text(cr, line, x, line_y, heading);
    line_y += 1.25 * size;
  }
  line_y += 0.15 * size;
  if (subtitle.empty()) return line_y;
  for (const std::string& line : wrap_text(cr, subtitle, sub, max_width)) {
    if (draw) draw_text(cr, line, x, line_y, sub);
    line_y += 1.2 * kFontSmall;
  }
  return line_y;
}

}  // namespace

double draw_title(cairo_t* cr, double x, double y, const std::string& title, const std::string& subtitle, double size,
                  double max_width) {
  return title_block(cr, x, y, title, subtitle, size, max_width, true);
}

namespace {

// `measure` run on a 1 x 1 scratch surface (text metrics before a canvas exists).
template <class Measure>
double measured(Measure&& measure) {
  cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1);
  cairo_t* cr = cairo_create(scratch);
  const double x = measure(cr);
  cairo_destroy(cr);
  cairo_surface_destroy(scratch);
  return x;
}

}  // namespace

double title_height(const std::string& title, const std::string& subtitle, double size, double max_width) {
  return measured([&](cairo_t* cr) { return title_block(cr, 0.0, 0.0, title, subtitle, size, max_width, false); });
}

double text_width(const std::string& text, const TextStyle& style) {
  TextStyle flat = style;
  flat.angle_deg = 0.0;
  return measured([&](cairo_t* cr) { return text_box(cr, text, flat).w; });
}

std::vector<std::string> wrap_text(const std::string& text, const TextStyle& style, double max_width) {
  std::vector<std::string> lines;
  measured([&](cairo_t* cr) {
    lines = wrap_text(cr, text, style, max_width);
    return 0.0;
  });
  return lines;
}

}  // namespace trapdem::plot
