#include "sinkhole_command.hpp"

#include <cmath>
#include <cstdio>
#include <fmt/format.h>

#include "core/length_text.hpp"
#include "analysis/sinkhole_json.hpp"
#include "study/sinkhole_run.hpp"
#include "core/errors.hpp"

namespace trapdem::app {

namespace {

std::string num(double x, const char* format) {
  return std::isfinite(x) ? fmt::format(fmt::runtime(format), x) : std::string("-");
}

std::string supposition_table(const SuppositionEstimate& e) {
  std::string s;
  s += fmt::format("  throat diameter D_throat = {:.2f} m\n", e.throat);
  s += fmt::format("  {:<6} {:>11} {:>15} {:>12} {:>17}\n", "layer", "thickness", "angle of draw", "2 t tan(a)",
                   "diameter at top");
  for (std::size_t i = 0; i < e.layers.size(); ++i) {
    const auto& c = e.layers[i];
    s += fmt::format("  {:<6} {:>9.2f} m {:>11.1f} deg {:>10.2f} m {:>15.2f} m\n", i + 1, c.layer.thickness,
                     c.layer.angle_of_draw_deg, c.widening, c.diameter_above);
  }
  s += fmt::format("  depth to throat {:.2f} m\n", e.total_thickness);
  s += fmt::format("  maximum surface diameter D_s = {:.2f} m: {} (SANS 1936 class {})\n", e.surface_diameter,
                   size_class_name(e.size_class), size_class_range(e.size_class));
  return s;
}

std::string plain_report(const SinkholeOptions& o) {
  if (o.throat.empty())
    throw InputError("--throat D is required: the diameter of the cavity throat the sinkhole starts from (m)");
  const double throat = parse_length(o.throat, "--throat");
  std::vector<BlanketLayer> layers;
  for (const auto& text : o.layers) layers.push_back(parse_layer(text, "--layer"));
  const SuppositionEstimate e = scenario_supposition(throat, layers);
  if (o.json) return to_json(e).dump() + "\n";
  return "Scenario supposition (Buttrick & Van Schalkwyk 1995; SANS 1936): D_s = D_throat + 2 sum t_i tan(alpha_i)\n" +
         supposition_table(e);
}

std::string from_report(const SinkholeOptions& o) {
  const DemRunGeometry run = read_dem_run(o.from);  // first: a missing analysis is the first thing to fix
  if (!o.throat.empty())
    throw InputError("--throat with --from: the throat is the run's trapdoor width scaled to prototype; leave "
                     "--throat out");
  if (o.layers.size() != 1)
    throw InputError(
        "--from needs one --layer :ANGLE_OF_DRAW, the angle of draw (degrees from the vertical) the supposition "
        "should assume for the run's blanket, e.g. --layer :30; trapdem has no default because the angle is chosen "
        "per blanket material and no published value could be verified (see docs/sinkhole.md)");
  const BlanketLayer assumed = parse_layer(o.layers.front(), "--layer", true);
  if (!std::isnan(assumed.thickness))
    throw InputError(fmt::format("--layer '{}' with --from: the thickness is the run's soil height scaled to "
                                 "prototype; give the angle only (--layer :{})",
                                 o.layers.front(), assumed.angle_of_draw_deg));
  const MechanismComparison c = compare_with_dem(run, assumed.angle_of_draw_deg);
  if (o.json) return to_json(c).dump() + "\n";

  const double n = run.g_level;
  std::string s;
  s += fmt::format("Sinkhole size from DEM run '{}' ({}), g level N = {:g}\n", run.name, o.from, n);
  s += fmt::format("  model: trapdoor B = {}, surface zone of influence = {}\n", format_mm(run.trapdoor_width),
                   format_mm(run.surface_zone_width));
  if (std::isfinite(run.travel) && std::isfinite(run.settlement_fraction))
    s += fmt::format("         (settlement over {:g} % of the trapdoor travel, {} analysed)\n",
                     100.0 * run.settlement_fraction, format_mm(run.travel));
  s += fmt::format("         soil height H = {} ({})\n", format_mm(run.soil_height), run.soil_height_source);
  s += fmt::format("  prototype (lengths x {:g}): throat {:.2f} m, blanket {:.2f} m\n", n, c.throat, c.thickness);
  s += "\n";
  s += fmt::format("  {:<38} {:>14} {:>12}  {}\n", "estimate", "angle of draw", "D_s", "SANS 1936 class");
  s += fmt::format("  {:<38} {:>10} deg {:>10.2f} m  {} ({})\n", "mechanism (DEM surface zone x N)",
                   num(c.angle_from_surface_deg, "{:.1f}"), c.dem_surface_diameter, size_class_name(c.dem_size_class),
                   size_class_range(c.dem_size_class));
  s += fmt::format("  {:<38} {:>10} deg {:>10.2f} m  {} ({})\n", "scenario supposition (assumed angle)",
                   num(c.assumed_angle_deg, "{:.1f}"), c.supposition.surface_diameter,
                   size_class_name(c.supposition.size_class), size_class_range(c.supposition.size_class));
  s += fmt::format("  ratio supposition / mechanism = {}\n", num(c.ratio, "{:.2f}"));
  s += "\n";
  s += fmt::format("  angle of draw the DEM implies: {} deg from the surface zone, atan((D_s - B) / 2H);\n",
                   num(c.angle_from_surface_deg, "{:.1f}"));
  s += fmt::format("    {} deg from the shear bands (left {}, right {}; degrees to the vertical, + outward)\n",
                   num(c.angle_from_bands_deg, "{:.1f}"), num(run.band_left_deg, "{:.1f}"),
                   num(run.band_right_deg, "{:.1f}"));
  for (const std::string& w : run.warnings) s += fmt::format("\nWARNING: {}\n", w);
  return s;
}

}  // namespace

std::string sinkhole_report(const SinkholeOptions& o) { return o.from.empty() ? plain_report(o) : from_report(o); }

int run_sinkhole(const SinkholeOptions& o) {
  const std::string text = sinkhole_report(o);
  std::fputs(text.c_str(), stdout);
  return 0;
}

}  // namespace trapdem::app
