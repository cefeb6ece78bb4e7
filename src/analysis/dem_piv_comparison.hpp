#pragma once
// DEM against PIV (issue 6, calibration against the centrifuge): the vertical displacement of a
// DEM run and of a PIV measurement on one regular grid, in model coordinates with the trapdoor
// centre as origin, and one error number over the area both cover. Plain functions on plain data
// (SI units); `trapdem compare` (apps/compare_command.cpp) reads the files and draws the figure.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "analysis/grid_field.hpp"
#include "analysis/point_set.hpp"

namespace trapdem {

// Scattered vertical displacements: w (m, up positive) at reference positions (m).
struct ScatteredDisplacement {
  std::vector<Point2> position;
  std::vector<double> w;
  double spacing = 0.0;  // m, typical distance between neighbours (PIV step, particle diameter)
};

// The grid of the given spacing over the intersection of the two point sets' bounding boxes,
// nodes at multiples of the spacing (so the origin, the trapdoor centre, is a node line).
// Throws InputError if the spacing is not positive, a set is empty or the boxes do not overlap.
GridSpec common_grid(const std::vector<Point2>& a, const std::vector<Point2>& b, double spacing);

// Linear interpolation of scattered values on `grid`: Delaunay triangles of the points, without
// those with an edge longer than max_edge_in_spacings x field.spacing or an angle below 10
// degrees (holes and the hull stay NaN). Throws InputError if fewer than three points.
GridField interpolate_scattered(const ScatteredDisplacement& field, const GridSpec& grid,
                                double max_edge_in_spacings = 1.5);

struct FieldComparison {
  std::size_t grid_nodes = 0;     // nodes of the common grid
  std::size_t compared = 0;       // nodes where both fields are defined
  double coverage = 0.0;          // compared / grid_nodes
  double trapdoor_displacement = 0.0;  // m, delta, the normalisation
  double rms = 0.0;               // m, sqrt(mean (w_a - w_b)^2) over the compared nodes
  double bias = 0.0;              // m, mean (w_a - w_b)
  double max_abs = 0.0;           // m, largest |w_a - w_b|
  double rms_normalised() const { return rms / trapdoor_displacement; }
  double bias_normalised() const { return bias / trapdoor_displacement; }
};

// Compares a (DEM) with b (PIV) node by node on the same grid. Throws InputError if the grids
// differ, delta is not positive, or no node has both values (no overlap).
FieldComparison compare_fields(const GridField& a, const GridField& b, double trapdoor_displacement);

// Both fields with NaN wherever either is undefined (the compared area, for contours).
void mask_to_common(GridField& a, GridField& b);

// --- piv.h5 (written by `trapdem piv`, layout in docs/piv.md) ------------------------------------

// The image names stored in piv.h5 (attribute "name" of /images/NNNNNN), image 1 first.
std::vector<std::string> piv_image_names(const std::filesystem::path& piv_h5);

// Vertical displacement from image `reference_image` to image `image` (1-based) of the subsets
// valid in both (in `image` only when reference_image is 1), at their model position in the
// reference image; model units converted to m (unit "mm", "cm" or "m") and then shifted so that
// `origin` (m, model coordinates) becomes (0, 0). spacing = the PIV step in m.
// Throws InputError if the file has no model coordinates (PIV run without --scale or
// --control-points), an index is out of range, or no subset is valid; FileError if unreadable.
ScatteredDisplacement read_piv_vertical_displacement(const std::filesystem::path& piv_h5, std::size_t reference_image,
                                                     std::size_t image, Point2 origin = {0.0, 0.0});

// The snapshot index in a `trapdem render` image name ("/x/camera/004_10mm.png" -> 4), or -1 if
// the name does not follow that pattern.
long rendered_snapshot_index(const std::string& image_name);

}  // namespace trapdem
