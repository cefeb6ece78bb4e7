#include "analysis/mechanism_shape.hpp"

#include <cmath>

#include <fmt/format.h>

namespace trapdem {

const char* mechanism_shape_name(MechanismShape shape) {
  switch (shape) {
    case MechanismShape::columnar: return "columnar";
    case MechanismShape::elliptical: return "elliptical";
    case MechanismShape::unknown: break;
  }
  return "unknown";
}

const char* mechanism_shape_basis_name(MechanismShapeBasis basis) {
  switch (basis) {
    case MechanismShapeBasis::bands: return "bands";
    case MechanismShapeBasis::zone_width: return "zone_width";
    case MechanismShapeBasis::none: break;
  }
  return "none";
}

namespace {

bool vertical_to_the_surface(const ShearBand& band, double layer_height, const MechanismShapeRule& rule) {
  return band.end != BandEnd::none && std::isfinite(band.angle_deg) &&
         std::fabs(band.angle_deg) <= rule.band_max_angle_deg &&
         band.height_reached >= rule.band_reach_fraction * layer_height;
}

}  // namespace

MechanismShapeResult classify_mechanism_shape(const ShearBandPair& bands, const ZoneOfInfluence& zone,
                                              const MechanismShapeRule& rule) {
  const double layer = zone.surface_height;
  if (std::isfinite(layer) && layer > 0.0 && vertical_to_the_surface(bands.left, layer, rule) &&
      vertical_to_the_surface(bands.right, layer, rule))
    return {MechanismShape::columnar, MechanismShapeBasis::bands};
  if (!std::isfinite(zone.shape_ratio)) return {};
  return {zone.shape_ratio < rule.columnar_shape_ratio ? MechanismShape::columnar : MechanismShape::elliptical,
          MechanismShapeBasis::zone_width};
}

std::string mechanism_shape_rule_text(const MechanismShapeRule& rule) {
  return fmt::format("columnar: both shear bands within {:g} deg of the vertical and traced to {:g} % of the layer's "
                     "height, or the zone's width at mid-height below {:g} B; else elliptical",
                     rule.band_max_angle_deg, 100.0 * rule.band_reach_fraction, rule.columnar_shape_ratio);
}

}  // namespace trapdem
