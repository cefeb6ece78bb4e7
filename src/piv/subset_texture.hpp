#pragma once
// Texture criteria against the "vermiculate" artefacts of poorly textured subsets (Stanier,
// Blaber, Take & White 2016, Comput. Geotech. 72: 100-113; the sum of squared subset intensity
// gradients, SSSIG, of Pan et al. 2008, Opt. Lasers Eng. 46: 460-470): a subset is used only if
// its intensity standard deviation and its SSSIG both reach a threshold. Intensities are on the
// 8-bit scale for every bit depth (grey_image.hpp), so the thresholds need no rescaling.
#include "piv/reference_subset.hpp"

namespace trapdem {

struct TextureCriteria {
  double min_intensity_std = 15.0;        // grey levels (8-bit scale)
  double min_sum_squared_gradient = 1e5;  // (grey levels / px)^2, summed over the subset, each direction
};

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
