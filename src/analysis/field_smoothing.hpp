#pragma once
// A per-triangle field (e.g. gamma_max) smoothed in the plane at a stated length: each triangle's
// value replaced by the area-weighted Gaussian average of the triangles around it. On a DEM field
// the strain of one triangle carries the non-affine motion of its three particles, correlated over
// a few diameters; averaging over a Gaussian of standard deviation L (a few d) suppresses that
// fluctuation while a shear band of full width W (~5-10 d) survives, widened to about
// sqrt(W^2 + (2.355 L)^2). The shear-band tracer and the smoothed strain figure read this field.
#include "analysis/grid_field.hpp"
#include "analysis/horizontal_profile.hpp"

namespace trapdem {

// v_s(c_i) = sum_j A_j K(|c_j - c_i|) v_j / sum_j A_j K(|c_j - c_i|), K(r) = exp(-r^2 / (2 L^2))
// truncated at 3 L, over the triangles with a finite value (normalised convolution: near the free
// surface and the walls only the triangles present count, so the edge is not pulled towards 0).
// A triangle whose value is NaN keeps NaN. length = 0 returns the field unchanged.
// Throws InputError if length is negative or not finite.
TriangleField smooth_triangle_field(const TriangleField& field, double length);

// The same Gaussian (truncated at 3 L) over a regular grid's nodes, each node weighted equally (a
// grid of a per-triangle field samples each triangle in proportion to its area, so this is the
// triangle smoothing's area weighting on the grid): the normalised convolution over the finite
// nodes, NaN nodes kept NaN. It smooths a stored field (field_history.h5) as the analysis smoothed
// the triangles it was sampled from. length = 0 returns the field unchanged. Throws InputError if
// length is negative or not finite.
GridField smooth_grid_field(const GridField& field, double length);

}  // namespace trapdem
