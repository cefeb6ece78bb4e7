#include "analysis/zone_of_influence.hpp"

#include "analysis/settlement_profile.hpp"
#include "core/errors.hpp"

namespace trapdem {

double deformed_zone_width_at_height(const PointSet2& points, const TrapdoorGeometry& trapdoor, double height,
                                     double slab_height, double column_width, double threshold) {
  const double z = trapdoor.base_z + height;
  const SettlementProfile profile =
      settlement_profile_in_slab(points, z - 0.5 * slab_height, z + 0.5 * slab_height, column_width);
  return width_where_settlement_exceeds(profile, trapdoor.centre_x, threshold);
}

ZoneOfInfluence zone_of_influence(const PointSet2& points, const TrapdoorGeometry& trapdoor,
                                  const ZoneOfInfluenceSettings& s) {
  if (!(s.mean_diameter > 0.0)) throw InputError("zone_of_influence: mean_diameter must be positive (m)");
  if (!(s.trapdoor_displacement > 0.0)) {
    throw InputError("zone_of_influence: trapdoor_displacement must be positive (m, downward travel)");
  }
  if (!(trapdoor.width > 0.0)) throw InputError("zone_of_influence: trapdoor width must be positive (m)");
  const double d = s.mean_diameter;
  const double column = s.column_width_diameters * d;
  const double slab = s.slab_height_diameters * d;

  ZoneOfInfluence zone;
  zone.threshold = s.settlement_fraction * s.trapdoor_displacement;
  const SettlementProfile surface = surface_settlement_profile(points, column, s.surface_layer_diameters * d);
  zone.surface_height = surface.surface_z - trapdoor.base_z;
  zone.surface_width = width_where_settlement_exceeds(surface, trapdoor.centre_x, zone.threshold);

  std::vector<double> heights = s.heights;
  if (heights.empty()) heights = {0.25 * zone.surface_height, 0.5 * zone.surface_height, 0.75 * zone.surface_height};
  for (double h : heights) {
    zone.widths.push_back({h, deformed_zone_width_at_height(points, trapdoor, h, slab, column, zone.threshold)});
  }
  zone.mid_height_width =
      deformed_zone_width_at_height(points, trapdoor, 0.5 * zone.surface_height, slab, column, zone.threshold);
  zone.shape_ratio = zone.mid_height_width / trapdoor.width;
  return zone;
}

}  // namespace trapdem
