// The mechanism's shape from the bands and the zone (analysis/mechanism_shape.hpp), on hand-made
// bands and zones: the paper-scale runs' own numbers, the rule's limits (inclusive), and each way
// the bands fail to make a column.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "analysis/mechanism_shape.hpp"

using namespace trapdem;

namespace {

constexpr double kB = 0.05;             // m, the trapdoor
constexpr double kLayer = 7.06 * kB;    // m above the trapdoor, the paper box's layer at 50 g

ShearBand band(double angle_deg, double height_over_layer, BandEnd end = BandEnd::lost) {
  ShearBand b;
  b.angle_deg = angle_deg;
  b.height_reached = height_over_layer * kLayer;
  b.end = end;
  return b;
}

ZoneOfInfluence zone(double shape_ratio, double layer = kLayer) {
  ZoneOfInfluence z;
  z.surface_height = layer;
  z.shape_ratio = shape_ratio;
  z.mid_height_width = shape_ratio * kB;
  return z;
}

MechanismShapeResult classify(const ShearBand& left, const ShearBand& right, const ZoneOfInfluence& z) {
  return classify_mechanism_shape(ShearBandPair{left, right}, z);
}

}  // namespace

// RF1 with elastic-plastic rolling at the paper's box (docs/results/equal-density-paper/cases/rf1-epsd):
// bands at 2.5 and 4.1 deg traced to 6.76 and 6.84 of the layer's 7.06 B, the 5 % zone 2.06 B wide
// at mid-height: a column by its bands. Calibrated seed 2 (docs/results/paper-replicates): bands at
// -5.2 and 0.2 deg that stop at 1.64 and 2.28 B, the zone 2.91 B: elliptical by the zone.
TEST(MechanismShape, ThePaperBoxRunsColumnAndEllipse) {
  const MechanismShapeResult rf1 = classify(band(2.5, 6.76 / 7.06), band(4.1, 6.84 / 7.06), zone(2.06));
  EXPECT_EQ(rf1.shape, MechanismShape::columnar);
  EXPECT_EQ(rf1.basis, MechanismShapeBasis::bands);
  const MechanismShapeResult calibrated = classify(band(-5.2, 1.64 / 7.06), band(0.2, 2.28 / 7.06), zone(2.91));
  EXPECT_EQ(calibrated.shape, MechanismShape::elliptical);
  EXPECT_EQ(calibrated.basis, MechanismShapeBasis::zone_width);
}

// The limits belong to the column (10 deg, 90 % of the layer), either sign of angle; just beyond
// either on one side, the zone decides.
TEST(MechanismShape, TheRulesLimitsAreInclusiveAndBothBandsMustMeetThem) {
  EXPECT_EQ(classify(band(10.0, 0.9), band(-10.0, 0.9), zone(2.0)).basis, MechanismShapeBasis::bands);
  EXPECT_EQ(classify(band(10.01, 0.95), band(2.0, 0.95), zone(2.0)).shape, MechanismShape::elliptical);
  EXPECT_EQ(classify(band(2.0, 0.95), band(2.0, 0.899), zone(2.0)).shape, MechanismShape::elliptical);
  EXPECT_EQ(classify(band(-15.0, 1.0), band(-15.0, 1.0), zone(2.0)).shape, MechanismShape::elliptical)
      << "inclined bands to the surface: a wedge";
}

// A band found at no edge (end none), an angle not measured, a layer height not measured: the
// bands cannot make a column, and the zone decides, or nothing does.
TEST(MechanismShape, WithoutBothBandsTheZoneDecidesAndWithoutItNothing) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(classify(band(2.0, 1.0, BandEnd::none), band(2.0, 1.0), zone(2.0)).shape, MechanismShape::elliptical);
  EXPECT_EQ(classify(band(nan, 1.0), band(2.0, 1.0), zone(2.0)).basis, MechanismShapeBasis::zone_width);
  EXPECT_EQ(classify(band(2.0, 1.0), band(2.0, 1.0), zone(2.0, 0.0)).basis, MechanismShapeBasis::zone_width);
  const MechanismShapeResult narrow = classify(ShearBand{}, ShearBand{}, zone(1.1));
  EXPECT_EQ(narrow.shape, MechanismShape::columnar);
  EXPECT_EQ(narrow.basis, MechanismShapeBasis::zone_width);
  const MechanismShapeResult none = classify(ShearBand{}, ShearBand{}, zone(nan));
  EXPECT_EQ(none.shape, MechanismShape::unknown);
  EXPECT_EQ(none.basis, MechanismShapeBasis::none);
  EXPECT_STREQ(mechanism_shape_name(none.shape), "unknown");
  EXPECT_STREQ(mechanism_shape_basis_name(MechanismShapeBasis::zone_width), "zone_width");
}
