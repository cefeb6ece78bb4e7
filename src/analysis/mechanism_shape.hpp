#pragma once
// The deformation mechanism's shape, columnar or elliptical, as the seed paper tells them apart:
// in its centrifuge sands "the two vertical shear bands reached the surface. The column of material
// between the two vertical shear bands then simply displaced downwards" (section 3), while "the
// shear bands of a material with a low shear strength are curved, with the associated deformation
// ellipsoid tending towards a circular shape" (section 5). So the bands decide first: both traced
// from the trapdoor's edges to near the surface, near the vertical, is a column whatever the
// settlement around it. Otherwise the zone of influence's width at mid-height decides (a zone
// about as wide as the door is a column too). The 5 % zone alone called a column "elliptical"
// where the column drags its neighbours down by more than 5 % of the travel (RF1 with
// elastic-plastic rolling at the paper's box: bands at 2.5 and 4.1 deg traced to 96 % of the
// layer, the zone at mid-height 2.06 B; docs/study.md).
#include <string>

#include "analysis/shear_bands.hpp"
#include "analysis/zone_of_influence.hpp"

namespace trapdem {

struct MechanismShapeRule {
  // Each band traced to at least this fraction of the layer's height above the trapdoor: a band
  // "reaches the surface" (its trace stops a few diameters short of it, where the strain data end
  // or the free surface's particles move alike; RF1's above stop at 0.96-0.97).
  double band_reach_fraction = 0.9;
  // Each band's fitted angle within this of the vertical (the paper-scale runs' bands scatter
  // +-5 deg between packings, docs/study.md; an inclined band to the surface is a wedge, not a column).
  double band_max_angle_deg = 10.0;
  // The zone's width at mid-height over B below this: columnar (a rigid column gives 1).
  double columnar_shape_ratio = 1.3;
};

enum class MechanismShape { unknown, columnar, elliptical };
const char* mechanism_shape_name(MechanismShape shape);

// What decided: the bands (both vertical to the surface), the zone's width, or nothing measured.
enum class MechanismShapeBasis { none, bands, zone_width };
const char* mechanism_shape_basis_name(MechanismShapeBasis basis);

struct MechanismShapeResult {
  MechanismShape shape = MechanismShape::unknown;
  MechanismShapeBasis basis = MechanismShapeBasis::none;
};

// Both bands found, each within rule.band_max_angle_deg of the vertical and traced to
// rule.band_reach_fraction of the layer (zone.surface_height above the trapdoor): columnar by the
// bands. Else by zone.shape_ratio (below rule.columnar_shape_ratio columnar, else elliptical);
// unknown without a finite shape ratio.
MechanismShapeResult classify_mechanism_shape(const ShearBandPair& bands, const ZoneOfInfluence& zone,
                                              const MechanismShapeRule& rule = {});

// The rule in words, for the report's findings: "columnar: both shear bands within 10 deg of the
// vertical and traced to 90 % of the layer's height, or ...; else elliptical".
std::string mechanism_shape_rule_text(const MechanismShapeRule& rule = {});

}  // namespace trapdem
