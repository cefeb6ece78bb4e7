// A canvas lets go of what it drew once it is gone, whatever format it was written in (issue 14:
// LeakSanitizer found 6.9 MB of drawing commands and a photograph left behind after SVG output).
// cairo 1.16's SVG backend keeps a reference to the recording surface painted onto it; the canvas
// finishes its recording, which frees the commands and the images they hold (tests/lsan.supp has
// the evidence). The witness is a piece of mime data attached to an image drawn into the canvas:
// the recording keeps a snapshot of the image, which shares the image's mime data, and cairo calls
// the mime data's destroy function when the last surface holding it is freed.
#include <gtest/gtest.h>

#include <cairo.h>

#include <string>

#include "../io/io_test_support.hpp"
#include "plot/canvas.hpp"

using namespace trapdem;

namespace {

// Draws a 40 x 30 image into a canvas, writes the canvas as `file` and destroys it; true if the
// image was freed by then.
bool image_freed_after_writing(const std::string& file) {
  io_testing::ScratchDir dir;
  bool freed = false;
  {
    plot::Canvas canvas(200, 100);
    cairo_surface_t* image = cairo_image_surface_create(CAIRO_FORMAT_RGB24, 40, 30);
    static const unsigned char bytes[] = {1, 2, 3};
    cairo_surface_set_mime_data(image, "application/x-trapdem-witness", bytes, sizeof bytes,
                                [](void* flag) { *static_cast<bool*>(flag) = true; }, &freed);
    cairo_set_source_surface(canvas.cr(), image, 10.0, 10.0);
    cairo_paint(canvas.cr());
    cairo_surface_destroy(image);  // the canvas's recording holds it now
    canvas.write(dir / file);
    EXPECT_FALSE(freed) << "the recording still needs the image while the canvas lives";
  }
  return freed;
}

TEST(CanvasRelease, TheImagesItDrewAreFreedAfterSvgPdfAndPngOutput) {
  EXPECT_TRUE(image_freed_after_writing("figure.svg"));
  EXPECT_TRUE(image_freed_after_writing("figure.pdf"));
  EXPECT_TRUE(image_freed_after_writing("figure.png"));
}

}  // namespace
