#pragma once
// The two shear bands of a trapdoor test, read off the maximum shear strain field: in height
// slabs from the trapdoor upward, the strain ridge left and right of the trapdoor centre, each
// followed as one continuous ridge from its trapdoor edge (ridges that branch off it are reported
// as branches, never jumped to). From the trace: the band's angle to the vertical with its
// standard error (least squares over a height range, and near the base), the height it reaches,
// its width in particle diameters. These turn the paper's "more vertical" and "narrower"
// (sections 5 and 6) into numbers. The rule is stated in docs/analysis.md.
#include <cstddef>
#include <limits>
#include <vector>

#include "analysis/horizontal_profile.hpp"
#include "analysis/trapdoor_geometry.hpp"

namespace trapdem {

enum class BandSide { left, right };

struct ShearBandSettings {
  double mean_diameter = 0.0;               // m, d; must be positive
  // Gaussian smoothing of the strain field in the plane (standard deviation, in d) before the
  // ridges are traced (field_smoothing.hpp); 0: none. Default 2 d: the triangle-scale fluctuation
  // of a DEM field (correlated over 1-3 d) is averaged over about 10 d^2 of triangles, while a
  // band of full width 5-10 d is widened by only 4-20 % (sqrt(W^2 + (2.355 L)^2)).
  double smoothing_diameters = 2.0;
  double slab_height_diameters = 2.0;       // height of one slab (one trace point), in d
  double profile_spacing_diameters = 0.25;  // sample spacing of each horizontal profile, in d
  double kernel_width_diameters = 0.5;      // Gaussian smoothing along x (standard deviation), in d
  double base_search_fraction = 0.25;       // first slab: ridge searched within +/- this * B of the edge
  double max_lean_deg = 60.0;               // while the trend is unknown: window slab * tan(this) + d
  double max_step_diameters = 2.0;          // once known: the ridge within this of the trend's prediction
  std::size_t direction_points = 5;         // the trend: line through the last this many trace points
  std::size_t max_gap_slabs = 2;            // slabs without a ridge in the window bridged before stopping
  double min_prominence_fraction = 0.1;     // a ridge stands above its valleys by this * its value
  double ridge_threshold = 0.05;            // gamma_max; the band ends where its ridge drops below
  double min_branch_height_diameters = 10.0;  // a branch is reported when traced over at least this
  double min_branch_peak_fraction = 0.5;    // and its median ridge value is at least this * the band's
  double branch_reach_diameters = 10.0;     // a branch appears within this of the band (x, in d)
  double fit_height_min = 0.0;              // m above the trapdoor: range of the angle fit
  double fit_height_max = std::numeric_limits<double>::infinity();
  double base_fit_height_diameters = 10.0;  // base angle: fit over the lowest this many d
  double max_half_width_diameters = 10.0;   // a half-maximum crossing farther than this is not found
};

struct BandTracePoint {
  double z = 0.0;                 // m, slab centre
  double x = 0.0;                 // m, band centre (half-maximum mid-point, unsmoothed, at the smoothed ridge)
  double peak = 0.0;              // gamma_max at the ridge (smoothed field)
  double horizontal_width = 0.0;  // m, full width at half the ridge value along x, unsmoothed field (NaN if not found)
};

// Why a trace stopped.
enum class BandEnd {
  none,            // no ridge above the threshold at the trapdoor edge: no band
  below_threshold, // the ridge value dropped below ridge_threshold
  centre_line,     // the ridge ran into the trapdoor centre line (met the other band)
  lost,            // no ridge within the step window for more than max_gap_slabs slabs
  top,             // the top of the strain data
};
const char* band_end_name(BandEnd end);

// A least-squares line x = a + b z through trace points, with the standard error of b.
struct TraceLineFit {
  std::size_t points = 0;
  double slope = std::numeric_limits<double>::quiet_NaN();      // b = dx/dz
  double intercept = std::numeric_limits<double>::quiet_NaN();  // a, m
  // Standard error of b: sqrt(s^2 / sum (z - mean z)^2) with s^2 = sum r^2 / (n_eff - 2) over the
  // residuals r; n_eff = n (1 - rho) / (1 + rho) for a lag-one autocorrelation rho > 0 of the
  // residuals (neighbouring trace points on a smoothed field are not independent; Santer et al.
  // 2000, J. Geophys. Res. 105(D6), eq. 6). NaN with n_eff <= 2.
  double slope_error = std::numeric_limits<double>::quiet_NaN();
  double residual_correlation = std::numeric_limits<double>::quiet_NaN();  // rho
};

// A ridge leaving the band: where it leaves (the height where its fitted line meets the band's
// trace) and its own trace and angle (same sign convention as the band's).
struct BandBranch {
  double height = 0.0;  // m above the trapdoor where the branch leaves the band
  std::vector<BandTracePoint> trace;
  double angle_deg = std::numeric_limits<double>::quiet_NaN();
  double angle_error_deg = std::numeric_limits<double>::quiet_NaN();
};

struct ShearBand {
  BandSide side = BandSide::left;
  std::vector<BandTracePoint> trace;  // from the trapdoor upward, one continuous ridge
  double height_reached = 0.0;        // m above the trapdoor where the trace ends (see `end`)
  BandEnd end = BandEnd::none;
  double angle_deg = std::numeric_limits<double>::quiet_NaN();        // to the vertical, fit range
  double angle_error_deg = std::numeric_limits<double>::quiet_NaN();  // standard error of angle_deg
  double base_angle_deg = std::numeric_limits<double>::quiet_NaN();   // to the vertical, near the base
  double base_angle_error_deg = std::numeric_limits<double>::quiet_NaN();
  double width_diameters = std::numeric_limits<double>::quiet_NaN();  // median width normal to the band / d
  std::vector<BandBranch> branches;   // ridges leaving the band, by height
};

struct ShearBandPair {
  ShearBand left;
  ShearBand right;
};

// Traces both bands in `gamma_max` (per triangle, normally in the reference geometry), smoothed
// at settings.smoothing_diameters first. Throws InputError if mean_diameter or the trapdoor width
// is not positive.
ShearBandPair trace_shear_bands(const TriangleField& gamma_max, const TrapdoorGeometry& trapdoor,
                                const ShearBandSettings& settings);

// The same with the smoothed field given (`smoothed`: same triangles as `gamma_max`, e.g. from
// smooth_triangle_field at settings.smoothing_diameters): ridges from `smoothed`, widths from
// `gamma_max`.
ShearBandPair trace_shear_bands(const TriangleField& gamma_max, const TriangleField& smoothed,
                                const TrapdoorGeometry& trapdoor, const ShearBandSettings& settings);

// One band: the ridge on `side`, starting at that trapdoor edge.
ShearBand trace_shear_band(const TriangleField& gamma_max, const TriangleField& smoothed,
                           const TrapdoorGeometry& trapdoor, const ShearBandSettings& settings, BandSide side);

// Least-squares line through the trace points with height above the trapdoor in
// [height_min, height_max] (fewer than three points: NaN slope).
TraceLineFit fit_trace_line(const std::vector<BandTracePoint>& trace, double base_z, double height_min,
                            double height_max);

// Angle to the vertical (degrees) of a slope dx/dz: positive when the band leans outward (away
// from the trapdoor centre) going up: atan(-b) on the left, atan(b) on the right.
double band_angle_from_slope(double slope, BandSide side);
// Its standard error in degrees: slope_error / (1 + b^2) (d atan(b) / db), in degrees.
double band_angle_error_from_fit(const TraceLineFit& fit);

// band_angle_from_slope(fit_trace_line(...).slope, side). NaN with fewer than three points.
double band_angle_deg(const std::vector<BandTracePoint>& trace, BandSide side, double base_z, double height_min,
                      double height_max);

// Median over the trace points in the height range of horizontal_width * cos(angle), the width
// normal to a band at angle_deg to the vertical, in metres. NaN if no point has a width.
double band_normal_width(const std::vector<BandTracePoint>& trace, double angle_deg, double base_z,
                         double height_min, double height_max);

}  // namespace trapdem
