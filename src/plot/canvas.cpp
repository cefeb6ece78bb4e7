#include "plot/canvas.hpp"

#include <cairo-pdf.h>
#include <cairo-svg.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include "core/text_escape.hpp"
#include "io/atomic_file.hpp"
#include "plot/figure_format.hpp"

namespace trapdem::plot {

namespace {

void check(cairo_status_t status, const char* what) {
  if (status != CAIRO_STATUS_SUCCESS) {
    throw std::runtime_error(std::string("cairo cannot write the ") + what + ": " + cairo_status_to_string(status));
  }
}

// Replays the recording onto `target` (scaled by `scale`) and finishes the target.
void replay(cairo_surface_t* recording, cairo_surface_t* target, double scale, const char* what) {
  check(cairo_surface_status(target), what);
  cairo_t* cr = cairo_create(target);
  cairo_scale(cr, scale, scale);
  cairo_set_source_surface(cr, recording, 0.0, 0.0);
  cairo_paint(cr);
  const cairo_status_t status = cairo_status(cr);
  cairo_destroy(cr);
  check(status, what);
  cairo_surface_flush(target);
}

// A surface destroyed at the end of its scope, whatever happens.
struct SurfaceDestroy {
  void operator()(cairo_surface_t* s) const { cairo_surface_destroy(s); }
};
using Surface = std::unique_ptr<cairo_surface_t, SurfaceDestroy>;

// Finishes a vector surface (its file or stream complete) and checks for errors.
void finish(cairo_surface_t* s, const char* what) {
  cairo_surface_finish(s);
  check(cairo_surface_status(s), what);
}

cairo_status_t append_to_string(void* closure, const unsigned char* data, unsigned int length) {
  static_cast<std::string*>(closure)->append(reinterpret_cast<const char*>(data), length);
  return CAIRO_STATUS_SUCCESS;
}

}  // namespace

Canvas::Canvas(int width, int height) : width_(width), height_(height) {
  const cairo_rectangle_t extents{0.0, 0.0, static_cast<double>(width), static_cast<double>(height)};
  surface_ = cairo_recording_surface_create(CAIRO_CONTENT_COLOR, &extents);
  if (cairo_surface_status(surface_) != CAIRO_STATUS_SUCCESS) {
    const std::string why = cairo_status_to_string(cairo_surface_status(surface_));
    cairo_surface_destroy(surface_);
    throw std::runtime_error("cannot create a " + std::to_string(width) + " x " + std::to_string(height) +
                             " figure: " + why);
  }
  cr_ = cairo_create(surface_);
  cairo_set_source_rgb(cr_, 1.0, 1.0, 1.0);
  cairo_paint(cr_);
}

Canvas::~Canvas() {
  cairo_destroy(cr_);
  // Finished before the last reference goes: cairo 1.16's SVG backend keeps a reference to a
  // recording surface painted onto it (through the snapshot of the page it records) and never
  // drops it, so destroy alone would leave the recording, with every drawing command and image in
  // it, alive for ever (6.9 MB for a strain map written as SVG). Finishing frees what it holds;
  // only its own small struct stays with cairo's reference (tests/lsan.supp).
  cairo_surface_finish(surface_);
  cairo_surface_destroy(surface_);
}

void Canvas::write(const std::filesystem::path& path) const {
  const FigureFormat format = figure_format_of(path);
  cairo_surface_flush(surface_);
  write_atomically(path, [&](const std::filesystem::path& temporary) {
    switch (format) {
      case FigureFormat::png: {
        const Surface image(cairo_image_surface_create(CAIRO_FORMAT_RGB24,
                                                       static_cast<int>(std::lround(width_ * kPngPixelsPerUnit)),
                                                       static_cast<int>(std::lround(height_ * kPngPixelsPerUnit))));
        replay(surface_, image.get(), kPngPixelsPerUnit, "PNG");
        check(cairo_surface_write_to_png(image.get(), temporary.c_str()), "PNG");
        break;
      }
      case FigureFormat::pdf: {
        const Surface pdf(cairo_pdf_surface_create(temporary.c_str(), width_, height_));
        if (!title_.empty()) cairo_pdf_surface_set_metadata(pdf.get(), CAIRO_PDF_METADATA_TITLE, title_.c_str());
        cairo_pdf_surface_set_metadata(pdf.get(), CAIRO_PDF_METADATA_CREATOR, "trapdem");
        replay(surface_, pdf.get(), 1.0, "PDF");
        finish(pdf.get(), "PDF");
        break;
      }
      case FigureFormat::svg: {
        // Written to memory first, to put the title in as text: cairo draws text as glyph outlines.
        std::string svg;
        {
          const Surface s(cairo_svg_surface_create_for_stream(append_to_string, &svg, width_, height_));
          replay(surface_, s.get(), 1.0, "SVG");
          finish(s.get(), "SVG");
        }
        if (!title_.empty()) {
          const std::size_t open = svg.find("<svg");
          const std::size_t end = open == std::string::npos ? open : svg.find('>', open);
          if (end != std::string::npos) svg.insert(end + 1, "\n<title>" + markup_escape(title_) + "</title>");
        }
        std::ofstream out(temporary, std::ios::binary);
        out.write(svg.data(), static_cast<std::streamsize>(svg.size()));
        out.close();
        if (!out) throw std::runtime_error("cannot write the SVG");
        break;
      }
    }
  });
}

void set_colour(cairo_t* cr, Rgb c, double alpha) { cairo_set_source_rgba(cr, c.r, c.g, c.b, alpha); }

}  // namespace trapdem::plot
