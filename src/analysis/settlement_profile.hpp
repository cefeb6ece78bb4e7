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

// The contiguous stretch around x_centre where settlement >= threshold: from the left crossing
// to the right one, each interpolated linearly between column centres. Empty (left = right =
// x_centre) if the column at x_centre is below the threshold. A stretch running into an empty
// column or the profile's end stops at the last column centre above the threshold; reaches_end
// says it ran to the profile's end (the outermost column: next to a side wall).
struct SettlementStretch {
  double left = 0.0, right = 0.0;  // m
  bool reaches_left_end = false, reaches_right_end = false;
  double width() const { return right - left; }
};
SettlementStretch stretch_where_settlement_exceeds(const SettlementProfile& profile, double x_centre,
                                                   double threshold);

// Its width (0 if the column at x_centre is below the threshold).
double width_where_settlement_exceeds(const SettlementProfile& profile, double x_centre, double threshold);

// Settlement in the outermost column with nodes on each side (m): next to the side walls.
struct EndSettlements {
  double left = 0.0, right = 0.0;
};
EndSettlements end_settlements(const SettlementProfile& profile);

}  // namespace trapdem
