#include "plot/element_figure.hpp"

#include "plot/canvas.hpp"
#include "plot/line_chart.hpp"

namespace trapdem::plot {

namespace {
constexpr int kWidth = static_cast<int>(kFigureWidth), kPanelHeight = 450;

std::vector<double> percent(const std::vector<double>& v) {
  std::vector<double> out(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) out[k] = 100.0 * v[k];
  return out;
}
}  // namespace

void write_element_figure(const std::filesystem::path& path, const std::string& title, const std::string& subtitle,
                              const std::vector<ElementCurve>& curves, const std::vector<double>& reference_sin_phi) {
  LineChart upper;
  upper.title = title;
  upper.subtitle = subtitle + (subtitle.empty() ? "" : "; ") + "mobilised sin φ' = (σ1 − σ3) / (σ1 + σ3)";
  upper.x_label = "axial strain (%)";
  upper.y_label = "sin φ' (-)";
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
  Canvas canvas(kWidth, 2 * kPanelHeight);
  canvas.set_title(title);
  draw_line_chart(canvas.cr(), {0.0, 0.0, static_cast<double>(kWidth), static_cast<double>(kPanelHeight)}, upper);
  draw_line_chart(canvas.cr(), {0.0, static_cast<double>(kPanelHeight), static_cast<double>(kWidth),
                                static_cast<double>(kPanelHeight)}, lower);
  canvas.write(path);
}

}  // namespace trapdem::plot
