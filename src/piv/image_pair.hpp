#pragma once
// One image pair: every subset of a reference image matched in the current image.
// 1. Subsets with a start (the previous image's warp, extrapolated) are refined by IC-GN, all in
//    parallel (OpenMP; each subset alone, so the result does not depend on the thread count);
//    kept only if converged with ZNCC >= reference_update_zncc (or if the subset left the image).
// 2. Seed candidates (every seed_spacing-th subset along each axis) not yet accepted get an
//    integer-pixel ZNCC search around their prediction (a match below min_valid_zncc is not
//    credible and is dropped), then IC-GN; in parallel.
// 3. Reliability-guided propagation (Pan 2009, Appl. Opt. 48(8): 1535-1542; as in GeoPIV-RG, Stanier
//    et al. 2016): the accepted subset with the highest ZNCC is taken next and each neighbour not
//    yet accepted is refined from its warp shifted to the neighbour's centre; accepted neighbours
//    join the queue. Sequential, with ties broken by subset index: deterministic.
// A subset is accepted (may seed others) if it is textured, converged and ZNCC >= min_valid_zncc.
#include <optional>
#include <vector>

#include "piv/icgn.hpp"
#include "piv/piv_settings.hpp"
#include "piv/prepared_image.hpp"
#include "piv/reference_subset.hpp"
#include "piv/subset_grid.hpp"

namespace trapdem {

// The subsets of one reference image, indexed like the grid: where they are and their texture.
// The IC-GN data of a subset (ReferenceSubset, 56 kB for L = 32) is rebuilt from the reference
// spline each time it is matched, so that tens of thousands of subsets of a 12-megapixel photograph
// need no gigabytes; rebuilding costs about one IC-GN iteration.
struct ReferenceSubsets {
  int subset_size = 0;                // px
  std::vector<cv::Point2d> centre;    // px, in the reference image
  std::vector<bool> present;          // inside the image, not lost, Hessian invertible
  std::vector<bool> textured;         // present and passes the texture criteria
  std::vector<double> intensity_std;  // grey levels; NaN if not present
  std::vector<double> sum_squared_gradient;  // SSSIG, (grey levels / px)^2; NaN if not present
};

ReferenceSubsets make_reference_subsets(const PreparedImage& reference, const std::vector<cv::Point2d>& centres,
                                        const std::vector<bool>& alive, int subset_size,
                                        const TextureCriteria& criteria, int threads = 0);

struct PairSolution {
  bool attempted = false;  // at least one IC-GN run
  IcgnResult best;         // converged over not, then highest ZNCC
};

// `start[i]`: the starting warp of subset i, if known; `prediction[i]`: the displacement (px)
// around which a seed candidate's integer search is centred.
std::vector<PairSolution> solve_image_pair(const SubsetGrid& grid, const ReferenceSubsets& reference_subsets,
                                           const PreparedImage& reference, const PreparedImage& current,
                                           const std::vector<std::optional<WarpParameters>>& start,
                                           const std::vector<cv::Point2d>& prediction, const PivSettings& settings);

// Whether a solution may be used and may seed its neighbours.
bool is_accepted(const PairSolution& s, bool textured, double min_valid_zncc);

}  // namespace trapdem
