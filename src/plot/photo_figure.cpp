#include "plot/photo_figure.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "plot/text.hpp"

namespace trapdem::plot {

namespace {

// The standard layout: canvas width and the margins around the frame (the top one below the title
// block), layout units.
constexpr double width = kFigureWidth, left = 4.4 * kFontSmall, right = 150.0, bottom = 3.5 * kFontSmall;

struct FrameMapping {
  PlotFrame frame;
  cairo_matrix_t pixel_to_device;
};

// The frame over the photograph's pixels fitted into `space`, and the affine pixel -> canvas map.
FrameMapping fit_photograph(int w, int h, const PixelToPlot& m, Rect space) {
  double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
  for (const auto& [cx, cy] : {std::array<double, 2>{-0.5, -0.5}, std::array<double, 2>{w - 0.5, -0.5},
                               std::array<double, 2>{-0.5, h - 0.5}, std::array<double, 2>{w - 0.5, h - 0.5}}) {
    const auto [px, pz] = pixel_to_plot(m, cx, cy);
    x0 = std::min(x0, px), x1 = std::max(x1, px), z0 = std::min(z0, pz), z1 = std::max(z1, pz);
  }
  const Range1 xr{x0, x1}, zr{z0, z1};
  const Rect plot = fit_equal_aspect(space, xr, zr);
  FrameMapping f{PlotFrame(plot, xr, zr), {}};
  // Affine part of the transform (a projective one is approximated by it).
  const double sx = plot.w / xr.span(), sz = plot.h / zr.span();
  const double fx0 = plot.x - xr.lo * sx, fy0 = plot.bottom() + zr.lo * sz;
  const double n = m[8];
  cairo_matrix_init(&f.pixel_to_device, sx * m[0] / n, -sz * m[3] / n, sx * m[1] / n, -sz * m[4] / n,
                    fx0 + sx * m[2] / n, fy0 - sz * m[5] / n);
  return f;
}

Rect frame_space(double top, double canvas_height) {
  return {left, top, width - left - right, canvas_height - top - bottom};
}

double title_block_height(const std::string& title, const std::string& subtitle) {
  return 10.0 + title_height(title, subtitle, kFontTitle, width - 20.0) + 6.0;
}

// Canvas height for a frame of the photograph's aspect ratio in the standard layout.
int canvas_height(int w, int h, const PixelToPlot& m, double top) {
  const FrameMapping probe = fit_photograph(w, h, m, {left, top, width - left - right, 1e6});
  return static_cast<int>(std::ceil(top + std::min(probe.frame.pixels().h, 1.2 * width) + bottom));
}

}  // namespace

std::array<double, 2> pixel_to_plot(const PixelToPlot& m, double x, double y) {
  // Summed in the order of a matrix-vector product, as OpenCV's Matx does (the same pixels).
  double h[3];
  for (int i = 0; i < 3; ++i) {
    double s = 0.0;
    s += m[3 * i] * x;
    s += m[3 * i + 1] * y;
    s += m[3 * i + 2] * 1.0;
    h[i] = s;
  }
  return {h[0] / h[2], h[1] / h[2]};
}

PhotoFigure::PhotoFigure(int photo_width, int photo_height, const PixelToPlot& m, const std::string& title,
                         const std::string& subtitle)
    : canvas_(static_cast<int>(width),
              canvas_height(photo_width, photo_height, m, title_block_height(title, subtitle))),
      frame_(fit_photograph(photo_width, photo_height, m,
                            frame_space(title_block_height(title, subtitle), canvas_.height()))
                 .frame) {
  pixel_to_device_ = fit_photograph(photo_width, photo_height, m,
                                    frame_space(title_block_height(title, subtitle), canvas_.height()))
                         .pixel_to_device;
  canvas_.set_title(title);
  draw_title(canvas_.cr(), 10.0, 10.0, title, subtitle, kFontTitle, width - 20.0);
}

std::array<double, 2> PhotoPlacement::device_of_pixel(double x, double y) const {
  cairo_matrix_transform_point(&pixel_to_device, &x, &y);
  return {x, y};
}

std::array<double, 2> PhotoFigure::device_of_pixel(double x, double y) const {
  return placement().device_of_pixel(x, y);
}

double PhotoFigure::device_per_pixel() const {
  const cairo_matrix_t& t = pixel_to_device_;
  return std::sqrt(std::abs(t.xx * t.yy - t.xy * t.yx));
}

void PhotoFigure::draw_photograph(const Photograph& photograph, double fade) {
  cairo_t* cr = canvas_.cr();
  // Grey to cairo's RGB24 (B, G, R, unused bytes of a native-endian 32-bit word), in a surface that
  // owns its pixels: the canvas records the drawing and replays it when the figure is written.
  cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_RGB24, photograph.width, photograph.height);
  cairo_surface_flush(s);
  unsigned char* data = cairo_image_surface_get_data(s);
  const int stride = cairo_image_surface_get_stride(s);
  for (int y = 0; data && y < photograph.height; ++y) {
    auto* row = reinterpret_cast<std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
    for (int x = 0; x < photograph.width; ++x) {
      const std::uint32_t g = photograph.grey[static_cast<std::size_t>(y) * photograph.width + x];
      row[x] = 0xff000000u | g << 16 | g << 8 | g;
    }
  }
  cairo_surface_mark_dirty(s);
  cairo_save(cr);
  frame_.clip(cr);
  cairo_set_source_rgb(cr, 0.0, 0.0, 0.0);
  cairo_paint(cr);
  cairo_transform(cr, &pixel_to_device_);
  cairo_set_source_surface(cr, s, -0.5, -0.5);
  cairo_pattern_set_filter(cairo_get_source(cr), CAIRO_FILTER_GOOD);
  cairo_paint(cr);
  cairo_restore(cr);
  if (fade > 0.0) {
    cairo_save(cr);
    frame_.clip(cr);
    cairo_set_source_rgba(cr, 1.0, 1.0, 1.0, fade);
    cairo_paint(cr);
    cairo_restore(cr);
  }
  cairo_surface_destroy(s);
}

void PhotoFigure::draw_axes(const std::string& unit) {
  AxesStyle a;
  a.x_label = fmt::format("x ({})", unit);
  a.y_label = unit == "px" ? "−y (px, rows upward)" : fmt::format("z ({}), up", unit);
  a.font_size = kFontSmall;
  a.max_x_ticks = std::max(3, static_cast<int>(frame_.pixels().w / (3.2 * kFontSmall)));
  a.max_y_ticks = std::max(3, static_cast<int>(frame_.pixels().h / (2.2 * kFontSmall)));
  plot::draw_axes(canvas_.cr(), frame_, a);
}

Rect PhotoFigure::colour_bar_rect() const {
  const Rect& p = frame_.pixels();
  return {p.right() + 14.0, p.y + 0.05 * p.h, 16.0, 0.9 * p.h};
}

}  // namespace trapdem::plot
