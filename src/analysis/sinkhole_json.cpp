#include "analysis/sinkhole_json.hpp"

namespace trapdem {

Json to_json(const SuppositionEstimate& e) {
  Json j = Json::object();
  j.set("method", "scenario supposition (Buttrick & Van Schalkwyk 1995; SANS 1936): D_s = D_throat + 2 sum t_i tan(alpha_i)");
  j.set("throat_m", e.throat);
  Json layers = Json::array();
  for (const auto& c : e.layers) {
    Json l = Json::object();
    l.set("thickness_m", c.layer.thickness);
    l.set("angle_of_draw_deg", c.layer.angle_of_draw_deg);
    l.set("widening_m", c.widening);
    l.set("diameter_at_top_m", c.diameter_above);
    layers.push_back(l);
  }
  j.set("layers", layers);
  j.set("depth_to_throat_m", e.total_thickness);
  j.set("surface_diameter_m", e.surface_diameter);
  j.set("size_class", size_class_name(e.size_class));
  j.set("size_class_range", size_class_range(e.size_class));
  return j;
}

Json to_json(const MechanismComparison& c) {
  Json j = Json::object();
  Json model = Json::object();
  model.set("case", c.run.name);
  model.set("g_level", c.run.g_level);
  model.set("trapdoor_width_m", c.run.trapdoor_width);
  model.set("soil_height_m", c.run.soil_height);
  model.set("soil_height_source", c.run.soil_height_source);
  model.set("fill_height_m", c.run.fill_height);
  model.set("trapdoor_travel_m", c.run.travel);
  model.set("settlement_fraction", c.run.settlement_fraction);
  model.set("surface_zone_width_m", c.run.surface_zone_width);
  model.set("band_left_angle_deg", c.run.band_left_deg);
  model.set("band_right_angle_deg", c.run.band_right_deg);
  Json warnings = Json::array();
  for (const std::string& w : c.run.warnings) warnings.push_back(w);
  model.set("warnings", warnings);
  j.set("model", model);

  Json dem = Json::object();
  dem.set("scaling", "centrifuge similitude: prototype length = model length x g_level");
  dem.set("throat_m", c.throat);
  dem.set("thickness_m", c.thickness);
  dem.set("surface_diameter_m", c.dem_surface_diameter);
  dem.set("size_class", size_class_name(c.dem_size_class));
  dem.set("angle_of_draw_from_surface_zone_deg", c.angle_from_surface_deg);
  dem.set("angle_of_draw_from_bands_deg", c.angle_from_bands_deg);
  j.set("mechanism", dem);

  Json sup = to_json(c.supposition);
  sup.set("assumed_angle_of_draw_deg", c.assumed_angle_deg);
  j.set("supposition", sup);
  j.set("ratio_supposition_over_mechanism", c.ratio);
  return j;
}

}  // namespace trapdem
