#pragma once
// The zone of influence of the trapdoor: how wide the ground that settles is, at the surface and
// inside the specimen, and whether the deformed zone is a column (width about B all the way up)
// or an ellipse (wider at mid-height). The paper's "narrower zone of influence" (sections 5-7).
#include <limits>
#include <vector>

#include "analysis/point_set.hpp"
#include "analysis/trapdoor_geometry.hpp"

namespace trapdem {

struct ZoneOfInfluenceSettings {
  double mean_diameter = 0.0;          // m, d; must be positive
  double trapdoor_displacement = 0.0;  // m, downward travel of the trapdoor; must be positive
  double settlement_fraction = 0.05;   // the zone is where settlement >= this * trapdoor_displacement
  double column_width_diameters = 2.0;   // column width of the settlement profiles, in d
  double slab_height_diameters = 2.0;    // slab height of the profiles inside the specimen, in d
  double surface_layer_diameters = 2.0;  // depth below each column's top counted as surface, in d
  std::vector<double> heights;  // m above the trapdoor; empty: 1/4, 1/2 and 3/4 of the layer height
  // Side-wall warning: a side wall holds the soil next to it up, so where the settlement beside a
  // wall is a sizeable part of the threshold the zone's edge (and a sinkhole size read from it)
  // is the box's, not the soil's. Warned when the settlement in the column next to a wall, at the
  // surface or at one of the heights, is at least this fraction of the threshold. Default 0.5:
  // on a Gaussian trough (Peck 1969) half the 5 % threshold lies only 0.27 i beyond the zone's
  // edge at 2.45 i (i the trough width parameter), so the wall is within reach of the edge.
  double wall_warning_fraction = 0.5;
};

struct ZoneWidth {
  double height = 0.0;  // m above the trapdoor
  double width = 0.0;   // m
};

struct ZoneOfInfluence {
  double threshold = 0.0;         // m, the settlement that counts as deformed
  double surface_height = 0.0;    // m above the trapdoor (median column top)
  double surface_width = 0.0;     // m, at the ground surface
  std::vector<ZoneWidth> widths;  // at the requested heights
  double mid_height_width = 0.0;  // m, at half the layer height
  double shape_ratio = std::numeric_limits<double>::quiet_NaN();  // mid_height_width / B: ~1 columnar, > 1 elliptical

  // The side walls (the outermost columns with nodes stand next to them).
  double surface_left = 0.0, surface_right = 0.0;  // m, x of the surface zone's edges
  double wall_left_x = 0.0, wall_right_x = 0.0;    // m, reference x of the outermost nodes
  double wall_settlement_left = 0.0;   // m, largest settlement in the column next to the left wall
  double wall_settlement_right = 0.0;  // m (surface and the heights; NaN if no nodes there)
  bool reaches_wall = false;  // the zone (surface or a height) runs into a side wall's column
  bool wall_warning = false;  // reaches_wall, or a wall settlement >= wall_warning_fraction * threshold
};

// Throws InputError if mean_diameter, trapdoor_displacement or the trapdoor width is not positive.
ZoneOfInfluence zone_of_influence(const PointSet2& points, const TrapdoorGeometry& trapdoor,
                                  const ZoneOfInfluenceSettings& settings);

// Width of the zone with settlement >= threshold in the slab of slab_height centred at
// `height` above the trapdoor.
double deformed_zone_width_at_height(const PointSet2& points, const TrapdoorGeometry& trapdoor, double height,
                                     double slab_height, double column_width, double threshold);

}  // namespace trapdem
