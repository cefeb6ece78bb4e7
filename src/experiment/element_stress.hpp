#pragma once
// The element test's two stress measures, compression positive (Pa):
//
// Wall stress. Each wall's normal load over its face area: sigma_aa = -(F_w . n_w) / A_a, where
// F_w is the force the particles exert on wall w (Wall::force) and n_w its inward normal; an axis'
// value is the mean of its two walls.
//
// Contact (Love-Weber) stress, the average over the box volume V of the contact forces times their
// branch vectors (Love 1927; Weber 1966; Christoffersen et al. 1981):
//
//   sigma V = sum over particle pairs  f_ij (x) (x_i - x_j)
//           + sum over wall contacts   f_iw (x) (x_i - c_iw)
//
// with f_ij the force on i from j, f_iw the force on i from the wall touching it at the point c_iw
// (x_i - c_iw runs from the wall to the centre, so a wall pushing the particle in adds
// compression). The pair sum needs no pair list: since f_ji = -f_ij,
//   sum_pairs f_ij (x) (x_i - x_j) = sum_i F_i^pp (x) x_i,
// where F_i^pp is particle i's sum of pair forces, which the engine gives as Particles::force (the
// contact forces of the last step, gravity not included) less the particle's wall forces
// (WallList::force, per candidate). sum_i F_i^pp = 0, so positions may be taken from any origin
// (the box centre here, to keep the sum's terms small).
//
// In static equilibrium (F_i^pp + sum_w f_iw = 0 for every particle) the two agree exactly:
// sigma V = -sum_w f_iw (x) c_iw, the walls' forces times their positions, which on an axis is the
// wall load times the box length. The difference measures the specimen's inertia (sum m a (x) x).
#include <array>

#include "dem/simulation.hpp"
#include "experiment/element_box.hpp"

namespace trapdem {

using Stress3 = std::array<std::array<double, 3>, 3>;  // Pa, compression positive

// Normal stresses on the three axes from the walls (Pa, compression positive).
Vec3 wall_stress(const Simulation& sim, const ElementBox& box);
// One wall's normal stress (Pa, compression positive).
double wall_normal_stress(const Simulation& sim, const ElementBox& box, int axis, int side);
// The Love-Weber stress tensor over the box volume (Pa, compression positive), of the last step's forces;
// a clump's contacts referred to its centre of mass (Christoffersen et al. 1981), not its members'.
Stress3 love_weber_stress(const Simulation& sim, const ElementBox& box);

// The contact stress of the specimen's interior (Pa, compression positive): Love's sum over the
// particle pairs whose contact point lies in the sub-box `margin` (m) inside every wall,
//   sigma V_in = sum_{c in V_in} f_ij (x) (x_i - x_j),
// over its volume V_in. It leaves out the layers along the walls (ordered, looser: docs/element.md),
// which the wall stress and the whole-box sum include. A contact's force is recomputed from the
// pair's geometry and history with the particles' law: the normal model's elastic force less the
// normal dashpot, plus the tangential spring's force -k_t s (its dashpot, ~c_t |v_t| against
// k_t |s|, left out: a relative error of the order of the inertial number). The pairs straddling
// the sub-box's faces are counted whole when their contact point is in: a surface error of the
// order d / L_in in both the normal and the shear components alike (the stress ratio keeps it to
// second order). `margin` must leave an interior: throws SimulationError otherwise. NaN for a
// tangential model whose force is not its spring's (tangential_force_is_spring).
Stress3 interior_contact_stress(const Simulation& sim, const ElementBox& box, double margin);

}  // namespace trapdem
