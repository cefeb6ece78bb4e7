#pragma once
// Blaze-DEM's parameters that its two tangential forms (tangential_blaze_viscous.hpp,
// tangential_blaze_tresca.hpp) and its angular damping (rolling_angular_damping.hpp) share, declared
// once (contact/law_parameter.hpp): the strength factor mu_k, Blaze-DEM's own time step, which sets
// the force's scale and the damping's rate, and its two speeds.
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"

namespace trapdem {

inline constexpr LawParameter kBlazeStrengthFactor{
    "kinetic_friction", &ContactLaw::kinetic_friction, "", closed(0.0, kMaxLawFriction), "a friction coefficient >= 0",
    "static_friction", 1.0};
inline constexpr LawParameter kBlazeReferenceTimeStep{
    "reference_time_step", &ContactLaw::reference_time_step, "s", open_closed(0.0, kMaxReferenceTimeStep),
    "a positive time step (Blaze-DEM's dt)", {}, 1.0, false, true};
inline constexpr LawParameter kBlazeVelocityScale{
    "blaze_velocity_scale", &ContactLaw::blaze_velocity_scale, "m/s", open_closed(0.0, kMaxBlazeSpeed),
    "a positive speed", {}, 1.0, false, true};
inline constexpr LawParameter kBlazeRestSpeed{
    "blaze_rest_speed", &ContactLaw::blaze_rest_speed, "m/s", open_closed(0.0, kMaxBlazeSpeed), "a positive speed", {},
    1.0, false, true};

}  // namespace trapdem
