#pragma once
// Settlement along the width of the specimen: nodes grouped in vertical columns by their
// reference x, settlement = -w (downward positive, m) averaged per column, either in a height
// slab or in the top layer (the ground surface). Columns are Lagrangian (reference x).
#include <vector>

#include "analysis/point_set.hpp"

namespace trapdem {

struct SettlementProfile {
  std::vector<double> x;           // m, column centres, evenly spaced
  std::vector<double> settlement;  // m, downward positive; NaN for a column without nodes
  double surface_z = 0.0;          // m, median column top (surface profiles only)
};

// Columns of `column_width` spanning the reference bounding box; nodes with
// z_low <= z < z_high (reference). Throws InputError if column_width is not positive.
SettlementProfile settlement_profile_in_slab(const PointSet2& points, double z_low, double z_high,
                                             double column_width);

// The ground surface: in each column, the nodes within surface_layer_thickness of that column's
// highest node. surface_z is the median of the column tops.
SettlementProfile surface_settlement_profile(const PointSet2& points, double column_width,
                                             double surface_layer_thickness);

// Width of the contiguous stretch around x_centre where settlement >= threshold: from the left
// crossing to the right one, each interpolated linearly between column centres. 0 if the column
// at x_centre is below the threshold. A stretch running into an empty column or the profile's
// end stops at the last column centre above the threshold.
double width_where_settlement_exceeds(const SettlementProfile& profile, double x_centre, double threshold);

}  // namespace trapdem
