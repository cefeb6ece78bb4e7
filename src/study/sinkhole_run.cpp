#include "study/sinkhole_run.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "experiment/run_folder.hpp"
#include "io/text_file.hpp"

namespace fs = std::filesystem;

namespace trapdem {

DemRunGeometry read_dem_run(const fs::path& dir) {
  const RunFolder run(dir);
  const fs::path metrics_file = run.metrics_json();
  if (!fs::is_directory(dir)) throw InputError(fmt::format("--from {}: not a folder", dir.string()));
  const ExperimentConfig specimen = run.specimen(
      "--from needs a trapdem run folder (its resolved.toml has spin_up.g_level, the trapdoor width and the fill height)");
  if (!fs::exists(metrics_file))
    throw InputError(fmt::format("{}: not found; run `trapdem analyze {}` first (it writes the zone of influence "
                                 "at the surface and the band angles)",
                                 metrics_file.string(), dir.string()));

  DemRunGeometry g;
  g.name = specimen.name;
  g.g_level = specimen.spin_up.g_level;
  g.fill_height = specimen.pluviation.fill_height;

  const Json m = Json::parse(read_text_file(metrics_file), metrics_file.string());

  // The trapdoor width the analysis used (metrics), else the configuration's.
  g.trapdoor_width = json_number_or_nan(json_member_or_null(m, "trapdoor"), "width_m");
  if (!(g.trapdoor_width > 0.0)) g.trapdoor_width = specimen.trapdoor.width;
  g.travel = json_number_or_nan(json_member_or_null(m, "trapdoor"), "travel_m");

  const Json& zone = json_member_or_null(m, "zone_of_influence");
  g.surface_zone_width = json_number_or_nan(zone, "surface_width_m");
  g.settlement_fraction = json_number_or_nan(zone, "settlement_fraction");
  if (!(g.surface_zone_width > 0.0))
    throw InputError(fmt::format("{}: no zone_of_influence.surface_width_m (the analysis found no settlement "
                                 "zone at the surface); run `trapdem analyze {}` again at a larger trapdoor "
                                 "displacement",
                                 metrics_file.string(), dir.string()));
  const double measured = json_number_or_nan(zone, "surface_height_m");
  if (measured > 0.0) {
    g.soil_height = measured;
    g.soil_height_source = "the measured surface, metrics.json zone_of_influence.surface_height_m";
  } else if (g.fill_height > 0.0) {
    g.soil_height = g.fill_height;
    g.soil_height_source = "the nominal fill, resolved.toml pluviation.fill_height";
  } else {
    throw InputError(fmt::format("{}: no surface height in metrics.json and no pluviation.fill_height in "
                                 "resolved.toml: the soil height is unknown",
                                 dir.string()));
  }

  const Json& bands = json_member_or_null(m, "shear_bands");
  g.band_left_deg = json_number_or_nan(json_member_or_null(bands, "left"), "angle_deg");
  g.band_right_deg = json_number_or_nan(json_member_or_null(bands, "right"), "angle_deg");
  const Json& warnings = json_member_or_null(m, "warnings");
  for (std::size_t k = 0; warnings.type() == Json::Type::array && k < warnings.size(); ++k)
    g.warnings.push_back(warnings[k].as_string());
  return g;
}

}  // namespace trapdem
