#pragma once
// The lists of the contact law's sub-models, one per axis of its choices, each in the order of its
// enum (choices.hpp; ModelList checks it). A new model is a kernel file, its enum value with its
// configuration name (choices.hpp) and its entry here (docs/ARCHITECTURE.md, "Adding a contact law").
//
// What every model of an axis declares:
// - normal: `model`, `damping_scale`, `Params`, `params(law, particle_law)`, `respond(params,
//   overlap, R*)` -> NormalResponse, `time_scale(law, particle_law, mass, radius)`;
// - tangential: `model`, `needs_tangential_mass`, `Params`, `params(law)`, `force(params, history,
//   TangentialInputs)` -> TangentialResponse, `carries_spring_force` (its force is -k_t s of the
//   history's spring, as the element test's interior stress reads it);
// - rolling: `model`, `has_torque`, `keeps_rolling_spring`, `damps_spin`, `needs_spin_inertia`,
//   `needs_rolling_inertia(choices)`, `Params`, `params(law)`, `torque<choices>(params, history,
//   RollingInputs)`.
#include "dem/contact/model_list.hpp"
#include "dem/contact/normal_hertz.hpp"
#include "dem/contact/normal_linear.hpp"
#include "dem/contact/rolling_angular_damping.hpp"
#include "dem/contact/rolling_constant_torque.hpp"
#include "dem/contact/rolling_epsd.hpp"
#include "dem/contact/rolling_none.hpp"
#include "dem/contact/tangential_blaze_tresca.hpp"
#include "dem/contact/tangential_blaze_viscous.hpp"
#include "dem/contact/tangential_coulomb.hpp"

namespace trapdem {

using NormalModels = ModelList<NormalModel, NormalLinear, NormalHertz>;
using TangentialModels = ModelList<TangentialModel, CoulombTangential, BlazeViscousTangential, BlazeTrescaTangential>;
using RollingModels = ModelList<RollingModel, NoRolling, ConstantTorqueRolling, EpsdRolling, AngularDampingRolling>;

// Whether a law's contacts remember a rolling spring (pair_histories.hpp keeps it only then).
constexpr bool keeps_rolling_spring(const LawChoices& law) {
  return RollingModels::visit(law.rolling, [](auto model) { return decltype(model)::keeps_rolling_spring; });
}

// Whether a law's tangential force is its spring's, -k_t s (element_stress.cpp recomputes it so).
constexpr bool tangential_force_is_spring(const LawChoices& law) {
  return TangentialModels::visit(law.tangential, [](auto model) { return decltype(model)::carries_spring_force; });
}

// Whether a law's rolling model damps every particle's spin in the integrator (rolling_angular_damping.hpp).
constexpr bool damps_spin(const LawChoices& law) {
  return RollingModels::visit(law.rolling, [](auto model) { return decltype(model)::damps_spin; });
}

}  // namespace trapdem
