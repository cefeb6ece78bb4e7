#include "plot/canvas.hpp"

#include <stdexcept>
#include <string>

#include "io/atomic_file.hpp"

namespace trapdem::plot {

Canvas::Canvas(int width, int height) : width_(width), height_(height) {
  surface_ = cairo_image_surface_create(CAIRO_FORMAT_RGB24, width, height);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    cairo_surface_destroy(surface_);
    throw std::runtime_error("cannot create a " + std::to_string(width) + " x " + std::to_string(height) +
                             " image: " + cairo_status_to_string(cairo_surface_status(surface_)));
  }
  cr_ = cairo_create(surface_);
  cairo_set_source_rgb(cr_, 1.0, 1.0, 1.0);
  cairo_paint(cr_);
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  cairo_surface_destroy(surface_);
}

void Canvas::write_png(const std::filesystem::path& path) const {
  cairo_surface_flush(surface_);
  write_atomically(path, [&](const std::filesystem::path& temporary) {
    const cairo_status_t status = cairo_surface_write_to_png(surface_, temporary.c_str());
    if (status != CAIRO_STATUS_SUCCESS) {
      throw std::runtime_error(std::string("cairo cannot write the PNG: ") + cairo_status_to_string(status));
    }
  });
}

void set_colour(cairo_t* cr, Rgb c, double alpha) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

}  // namespace trapdem::plot
