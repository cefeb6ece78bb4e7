#pragma once
// Texture criteria against the "vermiculate" artefacts of poorly textured subsets (Stanier,
// Blaber, Take & White 2016, Comput. Geotech. 72: 100-113; the sum of squared subset intensity
// gradients, SSSIG, of Pan et al. 2008, Opt. Express 16: 7037-7048): a subset is used only if
// its intensity standard deviation and its SSSIG both reach a threshold. Intensities are on the
// 8-bit scale for every bit depth (grey_image.hpp), so the thresholds need no rescaling.
#include "piv/reference_subset.hpp"

namespace trapdem {

// The defaults suit fine natural sand photographed at 12 megapixels with 32 px subsets (the
// uplift photographs of shared/data: subset intensity standard deviation 5-15 grey levels, median
// SSSIG 2e4); they flag glare, shadows and blank markers. By Pan et al.'s estimate the random
// error of a subset at the SSSIG threshold is about sqrt(2) sigma_noise / sqrt(SSSIG), i.e.
// 0.02 px for 1 grey level of noise at 5e3.
struct TextureCriteria {
  double min_intensity_std = 5.0;         // grey levels (8-bit scale)
  double min_sum_squared_gradient = 5e3;  // (grey levels / px)^2, summed over the subset, each direction
};

// The thresholds of Stanier et al. (2016, Comput. Geotech. 72) for seeded, well-textured sand:
// standard deviation 15 grey levels, SSSIG 1e5 (formulas.md).
inline TextureCriteria stanier_2016_texture_criteria() { return {15.0, 1e5}; }

// SSSIG of the subset: the smaller of sum f_x^2 and sum f_y^2 (Pan et al. 2008 bound the
// displacement error along each axis by the SSSIG along that axis), (grey levels / px)^2.
inline double sum_squared_gradient(const ReferenceSubset& s) {
  return s.sum_squared_gradient_x < s.sum_squared_gradient_y ? s.sum_squared_gradient_x
                                                             : s.sum_squared_gradient_y;
}

inline bool has_enough_texture(const ReferenceSubset& s, const TextureCriteria& c) {
  return s.intensity_std >= c.min_intensity_std && sum_squared_gradient(s) >= c.min_sum_squared_gradient;
}

}  // namespace trapdem
