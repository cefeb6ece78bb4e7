#pragma once
// Sub-pixel refinement of one subset by inverse-compositional Gauss-Newton (IC-GN) on the
// zero-normalised sum of squared differences (ZNSSD), first-order shape function, cubic B-spline
// interpolation of the current image (Pan et al. 2013, Exp. Mech. 53: 1277-1289; Stanier et al.
// 2016, Can. Geotech. J. 53: 727-739; formulas.md):
//   C = sum [(f - f_mean)/df - (g - g_mean)/dg]^2,  df = sqrt(sum (f - f_mean)^2),  ZNCC = 1 - C/2
//   dp = -H^-1 sum (grad f . dW/dp)^T [f - f_mean - (df/dg)(g - g_mean)],  W(p) <- W(p) o W(dp)^-1
// converged when |dp| (gradients scaled by the half subset size) < tolerance.
#include "piv/bspline_image.hpp"
#include "piv/reference_subset.hpp"
#include "piv/subset_warp.hpp"

namespace trapdem {

struct IcgnSettings {
  double convergence_tolerance = 1e-3;  // px, on update_norm(dp, L / 2)
  int max_iterations = 50;
  double max_wander = 8.0;  // px: an iterate whose (u, v) moves farther than this from the start has
                            // diverged (starts are within a pixel or two of the answer)
};

enum class IcgnOutcome {
  converged,       // |dp| below the tolerance
  iteration_cap,   // max_iterations reached first
  left_image,      // a warped subset point fell outside the current image
  flat_target,     // the warped subset in the current image has no intensity variation
  singular_update, // W(dp) could not be inverted (a diverging iteration)
  wandered         // (u, v) moved more than max_wander from the start
};

struct IcgnResult {
  WarpParameters p;      // the last iterate (meaningful when converged)
  double znssd = 4.0;    // C at the last evaluated warp, in [0, 4]
  double zncc = -1.0;    // 1 - C/2, in [-1, 1]
  int iterations = 0;    // Gauss-Newton updates made
  IcgnOutcome outcome = IcgnOutcome::iteration_cap;
};

// Refines `start` (the warp of `reference` into `current`, relative to the reference subset's
// centre). The ZNSSD and ZNCC are those of the last warp evaluated, i.e. before the final update
// whose size is below the tolerance.
IcgnResult refine_subset(const ReferenceSubset& reference, const BSplineImage& current, const WarpParameters& start,
                         const IcgnSettings& settings);

}  // namespace trapdem
