#include "analysis/plane_strain.hpp"

#include <cmath>

namespace trapdem {

PlaneStrain small_strain(const DisplacementGradient& g) {
  // Tension-positive: e = (grad u + grad u^T) / 2; soil mechanics negates it (compression positive).
  return {-g.du_dx, -g.dw_dz, -(g.du_dz + g.dw_dx)};
}

double maximum_shear_strain(const PlaneStrain& e) { return std::hypot(e.exx - e.ezz, e.gamma_xz); }

double volumetric_strain(const PlaneStrain& e) { return e.exx + e.ezz; }

}  // namespace trapdem
