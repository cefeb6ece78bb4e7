#include "compare_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "core/json.hpp"
#include "core/length_text.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

int run_compare(const CompareOptions& o) {
  const CompareResult c = compare_directories(o);
  const double delta = c.trapdoor_travel();
  fs::path out;
  if (!o.no_figure) {
    out = o.out.empty() ? default_compare_figure(o, c) : fs::path(o.out);
    write_compare_figure(c, out);
  }
  if (o.json) {
    Json j = Json::object();
    j.set("case", c.geometry.name);
    j.set("trapdoor_displacement_m", delta);
    j.set("dem_reference_snapshot", c.dem_reference_label);
    j.set("dem_snapshot", c.dem_at_label);
    j.set("piv_reference_image", c.piv_reference_image);
    j.set("piv_image", c.piv_image);
    j.set("piv_image_name", c.piv_image_name);
    j.set("image_choice", c.image_choice);
    j.set("grid_spacing_m", c.dem.grid.spacing);
    j.set("grid_nodes", c.error.grid_nodes);
    j.set("compared_nodes", c.error.compared);
    j.set("coverage", c.error.coverage);
    j.set("rms_m", c.error.rms);
    j.set("bias_m", c.error.bias);
    j.set("max_abs_m", c.error.max_abs);
    j.set("rms_over_delta", c.error.rms_normalised());
    j.set("bias_over_delta", c.error.bias_normalised());
    j.set("figure", out.string());
    fmt::print("{}\n", j.dump());
    return 0;
  }
  fmt::print("{}: DEM against PIV at trapdoor displacement {} (DEM snapshots {} -> {})\n", c.geometry.name,
             format_mm(delta), c.dem_reference_label, c.dem_at_label);
  fmt::print("  PIV image {} ({}) from image {} ({}): {}\n", c.piv_image, c.piv_image_name, c.piv_reference_image,
             c.piv_reference_name, c.image_choice);
  fmt::print("  grid {}: {} of {} nodes compared ({})\n", format_mm(c.dem.grid.spacing), c.error.compared,
             c.error.grid_nodes, percent_text(c.error.coverage));
  fmt::print("  error RMS(w_DEM - w_PIV) / delta = {} (RMS {:.3f} mm, bias {:+.3f} mm = {}, largest {:.3f} mm)\n",
             percent_text(c.error.rms_normalised()), c.error.rms * 1e3, c.error.bias * 1e3,
             percent_text(c.error.bias_normalised()), c.error.max_abs * 1e3);
  if (!out.empty()) fmt::print("  figure: {}\n", out.string());
  return 0;
}

}  // namespace trapdem::app
