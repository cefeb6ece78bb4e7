#include "analysis/zone_of_influence.hpp"

#include <algorithm>
#include <cmath>

#include "analysis/settlement_profile.hpp"
#include "core/errors.hpp"

namespace trapdem {

namespace {

SettlementProfile profile_at_height(const PointSet2& points, const TrapdoorGeometry& trapdoor, double height,
                                    double slab_height, double column_width) {
  const double z = trapdoor.base_z + height;
  return settlement_profile_in_slab(points, z - 0.5 * slab_height, z + 0.5 * slab_height, column_width);
}

// Records one profile's settlement next to the walls and whether its zone runs into them.
void note_walls(ZoneOfInfluence& zone, const SettlementProfile& profile, const SettlementStretch& stretch) {
  const EndSettlements ends = end_settlements(profile);
  const auto larger = [](double a, double b) { return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b); };
  zone.wall_settlement_left = larger(zone.wall_settlement_left, ends.left);
  zone.wall_settlement_right = larger(zone.wall_settlement_right, ends.right);
  zone.reaches_wall = zone.reaches_wall || stretch.reaches_left_end || stretch.reaches_right_end;
}

}  // namespace

double deformed_zone_width_at_height(const PointSet2& points, const TrapdoorGeometry& trapdoor, double height,
                                     double slab_height, double column_width, double threshold) {
  return width_where_settlement_exceeds(profile_at_height(points, trapdoor, height, slab_height, column_width),
                                        trapdoor.centre_x, threshold);
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
  zone.wall_settlement_left = zone.wall_settlement_right = std::numeric_limits<double>::quiet_NaN();
  const SettlementProfile surface = surface_settlement_profile(points, column, s.surface_layer_diameters * d);
  zone.surface_height = surface.surface_z - trapdoor.base_z;
  const SettlementStretch surface_zone = stretch_where_settlement_exceeds(surface, trapdoor.centre_x, zone.threshold);
  zone.surface_width = surface_zone.width();
  zone.surface_left = surface_zone.left;
  zone.surface_right = surface_zone.right;
  note_walls(zone, surface, surface_zone);
  zone.wall_left_x = zone.wall_right_x = points.position.front().x;
  for (const auto& p : points.position) {
    zone.wall_left_x = std::min(zone.wall_left_x, p.x);
    zone.wall_right_x = std::max(zone.wall_right_x, p.x);
  }

  std::vector<double> heights = s.heights;
  if (heights.empty()) heights = {0.25 * zone.surface_height, 0.5 * zone.surface_height, 0.75 * zone.surface_height};
  for (double h : heights) {
    const SettlementProfile profile = profile_at_height(points, trapdoor, h, slab, column);
    const SettlementStretch stretch = stretch_where_settlement_exceeds(profile, trapdoor.centre_x, zone.threshold);
    note_walls(zone, profile, stretch);
    zone.widths.push_back({h, stretch.width()});
  }
  zone.mid_height_width =
      deformed_zone_width_at_height(points, trapdoor, 0.5 * zone.surface_height, slab, column, zone.threshold);
  zone.shape_ratio = zone.mid_height_width / trapdoor.width;
  const double warning_level = s.wall_warning_fraction * zone.threshold;
  zone.wall_warning = zone.reaches_wall || zone.wall_settlement_left >= warning_level ||
                      zone.wall_settlement_right >= warning_level;
  return zone;
}

}  // namespace trapdem
