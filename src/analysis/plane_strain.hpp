#pragma once
// Small (infinitesimal) plane strain from a displacement gradient, in the soil-mechanics sign
// convention: COMPRESSION POSITIVE. Normal strains are positive when a length shortens,
// volumetric strain is positive when the area decreases (contraction), negative for dilation.
// The shear strain is the engineering shear gamma_xz = 2 e_xz.
#include "analysis/cst_gradient.hpp"

namespace trapdem {

struct PlaneStrain {
  double exx = 0.0;       // -du/dx
  double ezz = 0.0;       // -dw/dz
  double gamma_xz = 0.0;  // -(du/dz + dw/dx), engineering shear
};

// e_xx = -du/dx, e_zz = -dw/dz, gamma_xz = -(du/dz + dw/dx): the tension-positive small strain of
// formulas.md negated as a whole (principal directions unchanged, principal values swap sign).
PlaneStrain small_strain(const DisplacementGradient& g);

// gamma_max = e_1 - e_3 = sqrt((e_xx - e_zz)^2 + gamma_xz^2), the diameter of Mohr's circle of
// strain (engineering shear); independent of the sign convention. White & Bolton (2004).
double maximum_shear_strain(const PlaneStrain& e);

// e_vol = e_xx + e_zz (plane strain, e_yy = 0); compression positive.
double volumetric_strain(const PlaneStrain& e);

}  // namespace trapdem
