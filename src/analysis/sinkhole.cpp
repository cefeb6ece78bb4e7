#include "analysis/sinkhole.hpp"

#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <numbers>

#include "core/length_text.hpp"
#include "core/errors.hpp"

namespace trapdem {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kDegree = std::numbers::pi / 180.0;

std::string_view trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return s.substr(first, last - first + 1);
}

double parse_angle(std::string_view text, std::string_view what, std::string_view whole) {
  std::string s(trim(text));
  if (s.size() > 3 && s.ends_with("deg")) s = std::string(trim(std::string_view(s).substr(0, s.size() - 3)));
  std::size_t used = 0;
  double value = kNaN;
  try {
    value = std::stod(s, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (s.empty() || used != s.size() || !std::isfinite(value))
    throw InputError(fmt::format("{} '{}': the angle of draw '{}' is not a number (degrees from the vertical)", what,
                                 whole, s));
  return value;
}

void check_layer(const BlanketLayer& l, std::string_view what) {
  if (!(l.thickness >= 0.0) && !std::isnan(l.thickness))
    throw InputError(fmt::format("{}: thickness {} m is negative; a blanket layer is at least 0 m thick", what,
                                 l.thickness));
  if (!(l.angle_of_draw_deg >= 0.0 && l.angle_of_draw_deg < 90.0))
    throw InputError(fmt::format("{}: angle of draw {} deg is outside [0, 90): it is measured from the vertical "
                                 "(0 = a vertical-sided collapse; 90 would be horizontal)",
                                 what, l.angle_of_draw_deg));
}

}  // namespace

SinkholeSizeClass classify_sinkhole(double d) {
  if (d < 2.0) return SinkholeSizeClass::small;
  if (d < 5.0) return SinkholeSizeClass::medium;
  if (d <= 15.0) return SinkholeSizeClass::large;
  return SinkholeSizeClass::very_large;
}

const char* size_class_name(SinkholeSizeClass c) {
  switch (c) {
    case SinkholeSizeClass::small: return "small";
    case SinkholeSizeClass::medium: return "medium";
    case SinkholeSizeClass::large: return "large";
    case SinkholeSizeClass::very_large: return "very large";
  }
  return "?";
}

const char* size_class_range(SinkholeSizeClass c) {
  switch (c) {
    case SinkholeSizeClass::small: return "< 2 m";
    case SinkholeSizeClass::medium: return "2-5 m";
    case SinkholeSizeClass::large: return "5-15 m";
    case SinkholeSizeClass::very_large: return "> 15 m";
  }
  return "?";
}

BlanketLayer parse_layer(std::string_view text, std::string_view what, bool angle_only) {
  const std::string whole(text);
  const auto colon = text.find(':');
  BlanketLayer l;
  if (colon == std::string_view::npos) {
    if (!angle_only)
      throw InputError(fmt::format("{} '{}': expected THICKNESS:ANGLE_OF_DRAW, e.g. 12:30 (12 m at 30 degrees from "
                                   "the vertical)",
                                   what, whole));
    l.thickness = kNaN;
    l.angle_of_draw_deg = parse_angle(text, what, whole);
  } else {
    if (text.find(':', colon + 1) != std::string_view::npos)
      throw InputError(fmt::format("{} '{}': expected one ':' between THICKNESS and ANGLE_OF_DRAW", what, whole));
    const std::string_view thickness = trim(text.substr(0, colon));
    if (thickness.empty()) {
      if (!angle_only)
        throw InputError(fmt::format("{} '{}': the thickness is missing (expected THICKNESS:ANGLE_OF_DRAW)", what,
                                     whole));
      l.thickness = kNaN;
    } else {
      l.thickness = parse_length(thickness, fmt::format("{} '{}' (thickness)", what, whole));
    }
    l.angle_of_draw_deg = parse_angle(text.substr(colon + 1), what, whole);
  }
  check_layer(l, fmt::format("{} '{}'", what, whole));
  return l;
}

SuppositionEstimate scenario_supposition(double throat, const std::vector<BlanketLayer>& layers) {
  if (!(throat > 0.0) || !std::isfinite(throat))
    throw InputError(fmt::format("--throat {} m: the cavity throat diameter must be a positive length", throat));
  if (layers.empty())
    throw InputError("no blanket layer: give at least one --layer THICKNESS:ANGLE_OF_DRAW (cavity upward)");
  SuppositionEstimate e;
  e.throat = throat;
  double d = throat;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const BlanketLayer& l = layers[i];
    if (!std::isfinite(l.thickness))
      throw InputError(fmt::format("layer {}: the thickness is missing", i + 1));
    check_layer(l, fmt::format("layer {}", i + 1));
    LayerContribution c;
    c.layer = l;
    c.widening = 2.0 * l.thickness * std::tan(l.angle_of_draw_deg * kDegree);
    d += c.widening;
    // Every input is finite, yet 2 t tan(alpha) can overflow (t = 1e308 m): no estimate is inf.
    if (!std::isfinite(d))
      throw InputError(fmt::format("layer {}: {:g} m at {:g} deg gives a surface diameter beyond any number (D_s = {} "
                                   "m); expected a thickness in metres that gives a finite D_s",
                                   i + 1, l.thickness, l.angle_of_draw_deg, d));
    c.diameter_above = d;
    e.total_thickness += l.thickness;
    e.layers.push_back(c);
  }
  e.surface_diameter = d;
  e.size_class = classify_sinkhole(d);
  return e;
}

double implied_angle_of_draw_deg(double surface_diameter, double throat, double thickness) {
  if (!(thickness > 0.0)) return kNaN;
  return std::atan((surface_diameter - throat) / (2.0 * thickness)) / kDegree;
}

MechanismComparison compare_with_dem(const DemRunGeometry& run, double assumed_angle_deg) {
  MechanismComparison c;
  c.run = run;
  const double n = run.g_level;
  c.throat = run.trapdoor_width * n;
  c.thickness = run.soil_height * n;
  c.dem_surface_diameter = run.surface_zone_width * n;
  c.dem_size_class = classify_sinkhole(c.dem_surface_diameter);
  c.angle_from_surface_deg = implied_angle_of_draw_deg(c.dem_surface_diameter, c.throat, c.thickness);
  const bool l = std::isfinite(run.band_left_deg), r = std::isfinite(run.band_right_deg);
  c.angle_from_bands_deg = l && r ? 0.5 * (run.band_left_deg + run.band_right_deg)
                           : l    ? run.band_left_deg
                           : r    ? run.band_right_deg
                                  : kNaN;
  c.assumed_angle_deg = assumed_angle_deg;
  c.supposition = scenario_supposition(c.throat, {BlanketLayer{c.thickness, assumed_angle_deg}});
  c.ratio = c.supposition.surface_diameter / c.dem_surface_diameter;
  return c;
}

}  // namespace trapdem
