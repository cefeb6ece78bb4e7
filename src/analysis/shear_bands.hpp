#pragma once
// The two shear bands of a trapdoor test, read off the maximum shear strain field: in height
// slabs from the trapdoor upward, the strain ridge left and right of the trapdoor centre, each
// traced from its trapdoor edge. From the trace: the band's angle to the vertical (least squares
// over a height range, and near the base), the height it reaches, its width in particle diameters.
// These turn the paper's "more vertical" and "narrower" (sections 5 and 6) into numbers.
#include <cstddef>
#include <limits>
#include <vector>

#include "analysis/horizontal_profile.hpp"
#include "analysis/trapdoor_geometry.hpp"

namespace trapdem {

enum class BandSide { left, right };

struct ShearBandSettings {
  double mean_diameter = 0.0;               // m, d; must be positive
  double slab_height_diameters = 2.0;       // height of one slab (one trace point), in d
  double profile_spacing_diameters = 0.25;  // sample spacing of each horizontal profile, in d
  double kernel_width_diameters = 0.5;      // Gaussian smoothing along x (standard deviation), in d
  double base_search_fraction = 0.25;       // first slab: ridge searched within +/- this * B of the edge
  double max_lean_deg = 60.0;               // next slab: ridge searched within slab * tan(this) + d
  double ridge_threshold = 0.05;            // gamma_max; the band ends where its ridge drops below
  double fit_height_min = 0.0;              // m above the trapdoor: range of the angle fit
  double fit_height_max = std::numeric_limits<double>::infinity();
  double base_fit_height_diameters = 10.0;  // base angle: fit over the lowest this many d
  double max_half_width_diameters = 10.0;   // a half-maximum crossing farther than this is not found
};

struct BandTracePoint {
  double z = 0.0;                 // m, slab centre
  double x = 0.0;                 // m, band centre: mid-point of the half-maximum crossings
  double peak = 0.0;              // gamma_max at the ridge (smoothed)
  double horizontal_width = 0.0;  // m, full width at half the ridge value along x (NaN if not found)
};

struct ShearBand {
  BandSide side = BandSide::left;
  std::vector<BandTracePoint> trace;  // from the trapdoor upward, while the ridge >= threshold
  double height_reached = 0.0;        // m above the trapdoor where the ridge drops below threshold
  double angle_deg = std::numeric_limits<double>::quiet_NaN();       // to the vertical, fit range
  double base_angle_deg = std::numeric_limits<double>::quiet_NaN();  // to the vertical, near the base
  double width_diameters = std::numeric_limits<double>::quiet_NaN();  // median width normal to the band / d
};

struct ShearBandPair {
  ShearBand left;
  ShearBand right;
};

// Traces both bands in `gamma_max` (per triangle, normally in the reference geometry).
// Throws InputError if mean_diameter or the trapdoor width is not positive.
ShearBandPair trace_shear_bands(const TriangleField& gamma_max, const TrapdoorGeometry& trapdoor,
                                const ShearBandSettings& settings);

// One band: the ridge on `side`, starting at that trapdoor edge.
ShearBand trace_shear_band(const TriangleField& gamma_max, const TrapdoorGeometry& trapdoor,
                           const ShearBandSettings& settings, BandSide side);

// Angle to the vertical (degrees) of the least-squares line x = a + b z through the trace
// points with height above the trapdoor in [height_min, height_max]; positive when the band
// leans outward (away from the trapdoor centre) going up: atan(-b) on the left, atan(b) on the
// right. NaN with fewer than three points.
double band_angle_deg(const std::vector<BandTracePoint>& trace, BandSide side, double base_z, double height_min,
                      double height_max);

// Median over the trace points in the height range of horizontal_width * cos(angle), the width
// normal to a band at angle_deg to the vertical, in metres. NaN if no point has a width.
double band_normal_width(const std::vector<BandTracePoint>& trace, double angle_deg, double base_z,
                         double height_min, double height_max);

}  // namespace trapdem
