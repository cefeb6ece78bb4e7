#include "study/case_summary.hpp"

#include <cmath>

#include "core/errors.hpp"
#include "experiment/run_folder.hpp"
#include "io/text_file.hpp"

namespace trapdem {

namespace {

// The mean of the finite values among a and b; NaN if neither is.
double mean_of_found(double a, double b) {
  if (std::isfinite(a) && std::isfinite(b)) return 0.5 * (a + b);
  if (std::isfinite(a)) return a;
  return b;
}

Json number(double x) { return std::isfinite(x) ? Json(x) : Json(); }

}  // namespace

void read_mechanism_metrics(const Json& m, CaseSummary& s) {
  const Json& trapdoor = json_member_or_null(m, "trapdoor");
  s.trapdoor_width = json_number_or_nan(trapdoor, "width_m");
  s.travel = json_number_or_nan(trapdoor, "travel_m");
  s.mean_diameter = json_number_or_nan(json_member_or_null(m, "particles"), "mean_diameter_m");

  const Json& bands = json_member_or_null(m, "shear_bands");
  const Json& left = json_member_or_null(bands, "left");
  const Json& right = json_member_or_null(bands, "right");
  s.band_angle_left_deg = json_number_or_nan(left, "angle_deg");
  s.band_angle_right_deg = json_number_or_nan(right, "angle_deg");
  s.band_angle_deg = mean_of_found(s.band_angle_left_deg, s.band_angle_right_deg);
  s.band_angle_left_error_deg = json_number_or_nan(left, "angle_error_deg");
  s.band_angle_right_error_deg = json_number_or_nan(right, "angle_error_deg");
  if (std::isfinite(s.band_angle_left_deg) && std::isfinite(s.band_angle_right_deg))
    s.band_angle_error_deg = 0.5 * std::hypot(s.band_angle_left_error_deg, s.band_angle_right_error_deg);
  else
    s.band_angle_error_deg = std::isfinite(s.band_angle_left_deg) ? s.band_angle_left_error_deg : s.band_angle_right_error_deg;
  s.band_height = mean_of_found(json_number_or_nan(left, "height_reached_m"), json_number_or_nan(right, "height_reached_m"));
  s.band_width_d = mean_of_found(json_number_or_nan(left, "width_diameters"), json_number_or_nan(right, "width_diameters"));

  const Json& zone = json_member_or_null(m, "zone_of_influence");
  s.zone_surface = json_number_or_nan(zone, "surface_width_m");
  s.zone_mid_height = json_number_or_nan(zone, "mid_height_width_m");
  s.shape_ratio = json_number_or_nan(zone, "shape_ratio");
  const Json& higher = json_member_or_null(zone, "at_higher_thresholds");
  for (std::size_t k = 0; higher.type() == Json::Type::array && k < higher.size(); ++k)
    if (json_number_or_nan(higher[k], "settlement_fraction") == 0.25) {
      s.zone_surface_25 = json_number_or_nan(higher[k], "surface_width_m");
      s.zone_mid_height_25 = json_number_or_nan(higher[k], "mid_height_width_m");
    }
  const Json& strain = json_member_or_null(m, "strain");
  s.gamma_max_p90 = json_number_or_nan(strain, "gamma_max_p90");
  s.volumetric_beside_walls = mean_of_found(json_number_or_nan(strain, "volumetric_beside_left_wall"),
                                            json_number_or_nan(strain, "volumetric_beside_right_wall"));
  const Json& shape = json_member_or_null(zone, "shape");
  s.shape = shape.type() == Json::Type::string ? shape.as_string() : "";

  s.warnings.clear();
  const Json& warnings = json_member_or_null(m, "warnings");
  for (std::size_t k = 0; warnings.type() == Json::Type::array && k < warnings.size(); ++k)
    s.warnings.push_back(warnings[k].as_string());
}

const std::vector<SummaryMetric>& summary_metrics() {
  static const std::vector<SummaryMetric> metrics = {
      {"trapdoor_width_m", &CaseSummary::trapdoor_width},
      {"travel_m", &CaseSummary::travel},
      {"mean_diameter_m", &CaseSummary::mean_diameter},
      {"band_angle_deg", &CaseSummary::band_angle_deg},
      {"band_angle_error_deg", &CaseSummary::band_angle_error_deg},
      {"band_angle_left_deg", &CaseSummary::band_angle_left_deg},
      {"band_angle_left_error_deg", &CaseSummary::band_angle_left_error_deg},
      {"band_angle_right_deg", &CaseSummary::band_angle_right_deg},
      {"band_angle_right_error_deg", &CaseSummary::band_angle_right_error_deg},
      {"band_height_m", &CaseSummary::band_height},
      {"band_width_diameters", &CaseSummary::band_width_d},
      {"zone_surface_m", &CaseSummary::zone_surface},
      {"zone_mid_height_m", &CaseSummary::zone_mid_height},
      {"shape_ratio", &CaseSummary::shape_ratio},
      {"zone_surface_25pct_m", &CaseSummary::zone_surface_25},
      {"zone_mid_height_25pct_m", &CaseSummary::zone_mid_height_25},
      {"gamma_max_p90", &CaseSummary::gamma_max_p90},
      {"volumetric_strain_beside_walls", &CaseSummary::volumetric_beside_walls},
      {"min_load_ratio", &CaseSummary::min_load_ratio},
      {"min_load_at_over_B", &CaseSummary::min_load_at_over_b},
      {"final_load_ratio", &CaseSummary::final_load_ratio},
      {"dem_surface_diameter_prototype_m", &CaseSummary::dem_surface_diameter},
      {"supposition_surface_diameter_prototype_m", &CaseSummary::supposition_surface_diameter},
      {"angle_of_draw_from_surface_deg", &CaseSummary::angle_from_surface_deg},
      {"phi_peak_deg", &CaseSummary::phi_peak_deg},
      {"phi_cs_deg", &CaseSummary::phi_cs_deg},
  };
  return metrics;
}

void read_ground_reaction(const std::vector<GroundReactionRow>& rows, double trapdoor_width, CaseSummary& s) {
  s.grc_x_over_b.clear();
  s.grc_trapdoor_ratio.clear();
  for (const GroundReactionRow& row : rows) {
    s.grc_x_over_b.push_back(row.trapdoor_displacement / trapdoor_width);
    s.grc_trapdoor_ratio.push_back(row.trapdoor.ratio);
    if (!(row.trapdoor.ratio >= s.min_load_ratio)) {  // also takes the first over NaN
      s.min_load_ratio = row.trapdoor.ratio;
      s.min_load_at_over_b = row.trapdoor_displacement / trapdoor_width;
    }
  }
  if (!rows.empty()) s.final_load_ratio = rows.back().trapdoor.ratio;
}

CaseCost read_case_cost(const std::filesystem::path& run_dir) {
  CaseCost cost;
  const std::filesystem::path file = RunFolder(run_dir).run_json();
  if (!std::filesystem::exists(file)) return cost;
  const Json j = Json::parse(read_text_file(file), file.string());
  cost.wall_seconds = json_number_or_nan(j, "wall_seconds");
  cost.particle_steps = json_number_or_nan(j, "particle_steps");
  cost.particle_steps_per_second = json_number_or_nan(j, "particle_steps_per_second");
  cost.particles = json_number_or_nan(j, "particles");
  cost.segments = json_number_or_nan(j, "segments");
  return cost;
}

void read_sinkhole_comparison(const MechanismComparison& c, CaseSummary& s) {
  s.dem_surface_diameter = c.dem_surface_diameter;
  s.supposition_surface_diameter = c.supposition.surface_diameter;
  s.angle_from_surface_deg = c.angle_from_surface_deg;
  s.dem_size_class = std::isfinite(c.dem_surface_diameter) ? size_class_name(c.dem_size_class) : "";
  s.supposition_size_class = size_class_name(c.supposition.size_class);
}

Json to_json(const CaseSummary& s) {
  Json j = Json::object();
  j.set("name", s.name);
  j.set("label", s.label);
  if (s.replicate) j.set("seed", static_cast<double>(s.seed));
  for (const SummaryMetric& m : summary_metrics()) j.set(m.key, number(s.*m.field));
  j.set("shape", s.shape);
  j.set("dem_size_class", s.dem_size_class);
  j.set("supposition_size_class", s.supposition_size_class);
  Json warnings = Json::array();
  for (const std::string& w : s.warnings) warnings.push_back(w);
  j.set("warnings", warnings);
  Json cost = Json::object();
  cost.set("wall_seconds", number(s.cost.wall_seconds));
  cost.set("particle_steps", number(s.cost.particle_steps));
  cost.set("particle_steps_per_second", number(s.cost.particle_steps_per_second));
  cost.set("particles", number(s.cost.particles));
  cost.set("segments", number(s.cost.segments));
  j.set("cost", cost);
  return j;
}

}  // namespace trapdem
