#include "analysis/shear_bands.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/errors.hpp"

namespace trapdem {

namespace {

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

bool in_height_range(double z, double base_z, double height_min, double height_max) {
  const double h = z - base_z;
  return h >= height_min && h <= height_max;
}

double median(std::vector<double> v) {
  if (v.empty()) return nan_value;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

}  // namespace

double band_angle_deg(const std::vector<BandTracePoint>& trace, BandSide side, double base_z, double height_min,
                      double height_max) {
  // Least squares x = a + b z.
  double n = 0, sz = 0, sx = 0, szz = 0, szx = 0;
  for (const auto& p : trace) {
    if (!in_height_range(p.z, base_z, height_min, height_max)) continue;
    n += 1;
    sz += p.z;
    sx += p.x;
    szz += p.z * p.z;
    szx += p.z * p.x;
  }
  if (n < 3) return nan_value;
  const double denominator = n * szz - sz * sz;
  if (denominator <= 0.0) return nan_value;
  const double slope = (n * szx - sz * sx) / denominator;  // dx/dz
  return degrees(std::atan(side == BandSide::left ? -slope : slope));
}

double band_normal_width(const std::vector<BandTracePoint>& trace, double angle_deg, double base_z,
                         double height_min, double height_max) {
  // A band at angle a to the vertical cut by a horizontal line: normal width = horizontal * cos(a).
  const double cosine = std::isfinite(angle_deg) ? std::cos(radians(angle_deg)) : 1.0;
  std::vector<double> widths;
  for (const auto& p : trace) {
    if (in_height_range(p.z, base_z, height_min, height_max) && std::isfinite(p.horizontal_width)) {
      widths.push_back(p.horizontal_width * cosine);
    }
  }
  return median(std::move(widths));
}

ShearBand trace_shear_band(const TriangleField& gamma_max, const TrapdoorGeometry& trapdoor,
                           const ShearBandSettings& s, BandSide side) {
  if (!(s.mean_diameter > 0.0)) throw InputError("trace_shear_band: mean_diameter must be positive (m)");
  if (!(trapdoor.width > 0.0)) throw InputError("trace_shear_band: trapdoor width must be positive (m)");
  const double d = s.mean_diameter;
  const double slab = s.slab_height_diameters * d;
  const double spacing = s.profile_spacing_diameters * d;
  const double kernel = s.kernel_width_diameters * d;
  const double max_half_width = s.max_half_width_diameters * d;
  const double step_reach = slab * std::tan(radians(s.max_lean_deg)) + d;

  double z_top = trapdoor.base_z;
  for (const auto& c : gamma_max.centroid) z_top = std::max(z_top, c.z);

  ShearBand band;
  band.side = side;
  double x_previous = side == BandSide::left ? trapdoor.left_edge() : trapdoor.right_edge();
  double reach = s.base_search_fraction * trapdoor.width;
  double previous_peak = nan_value, previous_z = nan_value;
  for (double z_low = trapdoor.base_z; z_low <= z_top; z_low += slab) {
    const double z = z_low + 0.5 * slab;
    // Search window, kept on this band's side of the trapdoor centre.
    double x_low = x_previous - reach, x_high = x_previous + reach;
    if (side == BandSide::left) x_high = std::min(x_high, trapdoor.centre_x);
    else x_low = std::max(x_low, trapdoor.centre_x);
    if (x_low > x_high) break;
    const HorizontalProfile profile =
        horizontal_profile(gamma_max, z_low, z_low + slab, x_low - max_half_width, x_high + max_half_width, spacing, kernel);
    const std::size_t peak = index_of_maximum(profile, x_low, x_high);
    if (peak == profile.x.size()) {  // no strain data at this height: top of the specimen
      band.height_reached = band.trace.empty() ? 0.0 : band.trace.back().z - trapdoor.base_z;
      break;
    }
    const double value = profile.value[peak];
    if (value < s.ridge_threshold) {
      // The ridge crosses the threshold between the last traced slab and this one (linear).
      band.height_reached =
          band.trace.empty()
              ? 0.0
              : previous_z + (previous_peak - s.ridge_threshold) / (previous_peak - value) * (z - previous_z) -
                    trapdoor.base_z;
      break;
    }
    // Band centre: mid-point of the half-maximum crossings, read where the profile is steepest,
    // so less sensitive to particle-scale noise than the maximum itself; the refined maximum if a
    // crossing is missing.
    const HalfMaximumCrossings half = half_maximum_crossings(profile, peak, max_half_width);
    const double centre = std::isfinite(half.width()) ? half.centre() : refined_peak_position(profile, peak);
    BandTracePoint point{z, centre, value, half.width()};
    band.trace.push_back(point);
    band.height_reached = z - trapdoor.base_z;
    x_previous = point.x;
    previous_peak = value;
    previous_z = z;
    reach = step_reach;
  }

  band.angle_deg = band_angle_deg(band.trace, side, trapdoor.base_z, s.fit_height_min, s.fit_height_max);
  band.base_angle_deg = band_angle_deg(band.trace, side, trapdoor.base_z, 0.0, s.base_fit_height_diameters * d);
  band.width_diameters =
      band_normal_width(band.trace, band.angle_deg, trapdoor.base_z, s.fit_height_min, s.fit_height_max) / d;
  return band;
}

ShearBandPair trace_shear_bands(const TriangleField& gamma_max, const TrapdoorGeometry& trapdoor,
                                const ShearBandSettings& settings) {
  return {trace_shear_band(gamma_max, trapdoor, settings, BandSide::left),
          trace_shear_band(gamma_max, trapdoor, settings, BandSide::right)};
}

}  // namespace trapdem
