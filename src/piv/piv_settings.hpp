#pragma once
// The settings of a PIV run (GeoPIV-RG's choices by default: Stanier et al. 2016, Can. Geotech.
// J. 53: 727-739; formulas.md). Lengths in px of the first image.
#include <optional>

#include "piv/icgn.hpp"
#include "piv/subset_grid.hpp"
#include "piv/subset_texture.hpp"

namespace trapdem {

struct PivSettings {
  int subset_size = 32;                   // px, side L of the square subsets
  int step = 16;                          // px between subset centres
  std::optional<RegionOfInterest> roi;    // px, [x0, x1) x [y0, y1) of image 1; whole image if not set
  int search_radius = 16;                 // px, integer-pixel ZNCC search around the predicted displacement
  int seed_spacing = 4;                   // every seed_spacing-th subset along each axis is a seed candidate
  IcgnSettings icgn;                      // convergence tolerance 1e-3 px, at most 50 iterations
  TextureCriteria texture;                // std >= 5 grey levels, SSSIG >= 5e3 (8-bit scale)
  double min_valid_zncc = 0.6;            // a converged subset below this is flagged low_correlation
  double reference_update_zncc = 0.75;    // leapfrog: update the reference when a textured subset drops below
  int threads = 0;                        // OpenMP threads; 0: OpenMP's default
};

}  // namespace trapdem
