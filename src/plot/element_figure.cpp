#include "plot/element_figure.hpp"

#include <unistd.h>

#include <memory>

#include <cairo.h>
#include <fmt/format.h>

#include "core/errors.hpp"
#include "plot/canvas.hpp"
#include "plot/line_chart.hpp"

namespace trapdem::plot {

namespace {
constexpr int kWidth = 1000, kPanelHeight = 620;

std::vector<double> percent(const std::vector<double>& v) {
  std::vector<double> out(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) out[k] = 100.0 * v[k];
  return out;
}
}  // namespace

void write_element_figure_png(const std::filesystem::path& path, const std::string& title, const std::string& subtitle,
                              const std::vector<ElementCurve>& curves, const std::vector<double>& reference_sin_phi) {
  LineChart upper;
  upper.title = title;
  upper.subtitle = subtitle;
  upper.x_label = "axial strain (%)";
  upper.y_label = "sin phi' = (s1 - s3) / (s1 + s3)";
  upper.reference_y = reference_sin_phi;
  LineChart lower;
  lower.title = "Volumetric strain";
  lower.subtitle = "compression positive: dilation plots below zero";
  lower.x_label = "axial strain (%)";
  lower.y_label = "volumetric strain (%)";
  lower.y_min = 0.0;
  for (const ElementCurve& c : curves) {
    const std::vector<double> x = percent(c.axial_strain);
    upper.series.push_back({c.name, x, c.sin_phi, c.colour, c.dashed});
    lower.series.push_back({c.name, x, percent(c.volumetric_strain), c.colour, c.dashed});
  }
  // Each panel is drawn by the line chart into a temporary PNG beside the figure, then both are
  // stacked on one canvas.
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  const std::string stem = fmt::format(".{}.panel-{}", path.filename().string(), ::getpid());
  const std::filesystem::path top = dir / (stem + "-1.png"), bottom = dir / (stem + "-2.png");
  struct Remove {
    std::filesystem::path a, b;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove(a, ignored);
      std::filesystem::remove(b, ignored);
    }
  } remove_panels{top, bottom};
  write_line_chart_png(top, upper, kWidth, kPanelHeight);
  write_line_chart_png(bottom, lower, kWidth, kPanelHeight);

  Canvas canvas(kWidth, 2 * kPanelHeight);
  int offset = 0;
  for (const std::filesystem::path& panel : {top, bottom}) {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> image(
        cairo_image_surface_create_from_png(panel.c_str()), &cairo_surface_destroy);
    if (cairo_surface_status(image.get()) != CAIRO_STATUS_SUCCESS)
      throw FileError(fmt::format("{}: cannot read the panel just drawn: {}", panel.string(),
                                  cairo_status_to_string(cairo_surface_status(image.get()))));
    cairo_set_source_surface(canvas.cr(), image.get(), 0.0, offset);
    cairo_paint(canvas.cr());
    offset += kPanelHeight;
  }
  canvas.write_png(path);
}

}  // namespace trapdem::plot
