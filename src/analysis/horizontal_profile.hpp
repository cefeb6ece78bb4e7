#pragma once
// A per-triangle field (e.g. gamma_max) seen along a horizontal line: the triangles whose
// centroids fall in a height slab, averaged along x with a Gaussian kernel. The shear-band
// metrics read ridges and widths off these profiles.
#include <cstddef>
#include <vector>

#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"

namespace trapdem {

// One value per triangle, with the triangle's centroid and area (the averaging weight).
struct TriangleField {
  std::vector<Point2> centroid;  // m
  std::vector<double> area;      // m^2
  std::vector<double> value;

  std::size_t size() const { return value.size(); }
};

// Centroids and areas in the geometry `nodes` (normally the reference configuration).
// Throws InputError if value and mesh differ in size.
TriangleField make_triangle_field(const TriangleMesh& mesh, const std::vector<Point2>& nodes,
                                  const std::vector<double>& value);

struct HorizontalProfile {
  std::vector<double> x;      // m, sample positions, evenly spaced
  std::vector<double> value;  // NaN where no centroid lies within 3 kernel widths
};

// v(x) = sum A_t K(x - x_t) v_t / sum A_t K(x - x_t) over triangles with z_low <= z_t < z_high,
// K Gaussian with standard deviation kernel_width (truncated at 3 kernel widths), sampled at
// x_min, x_min + spacing, ... up to x_max. The kernel widens a band of true full width W to
// about sqrt(W^2 + (2.355 kernel_width)^2).
HorizontalProfile horizontal_profile(const TriangleField& field, double z_low, double z_high, double x_min,
                                     double x_max, double spacing, double kernel_width);

// Index of the largest finite value with x in [x_low, x_high]; profile.x.size() if there is none.
std::size_t index_of_maximum(const HorizontalProfile& profile, double x_low, double x_high);

// Position of the maximum refined by the parabola through the sample and its two neighbours
// (within half a spacing of the sample).
double refined_peak_position(const HorizontalProfile& profile, std::size_t peak);

struct HalfMaximumCrossings {
  double left = 0.0;   // m, x where the profile first drops to half the peak value, going left
  double right = 0.0;  // m, the same going right
  double width() const { return right - left; }            // full width at half maximum
  double centre() const { return 0.5 * (left + right); }   // mid-point, a robust band centre
};

// Crossings of value = peak value / 2 left and right of sample `peak`, each interpolated linearly
// between samples. A side is NaN if it does not drop to half within max_half_width of the peak
// or meets a NaN first.
HalfMaximumCrossings half_maximum_crossings(const HorizontalProfile& profile, std::size_t peak,
                                            double max_half_width);

// Full width at half maximum around sample `peak` (NaN if a crossing is not found).
double full_width_at_half_maximum(const HorizontalProfile& profile, std::size_t peak, double max_half_width);

}  // namespace trapdem
