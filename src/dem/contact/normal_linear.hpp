#pragma once
// Linear normal spring (the seed paper's eq. 1, F_n = k_n delta) with a constant tangential
// stiffness k_t (eq. 2).
#include <array>
#include <cstddef>
#include <string_view>
#include <cmath>

#include "dem/contact/choices.hpp"
#include "dem/contact/normal_response.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"

namespace trapdem {

struct NormalLinear {
  static constexpr NormalModel model = NormalModel::linear;
  // The restitution-based dashpot c = 2 beta sqrt(m* k) gives e exactly for a linear spring.
  static constexpr double damping_scale = 1.0;

  struct Params {
    double kn = 0.0;               // N/m
    double kt = 0.0;               // N/m
    double sqrt_kt_over_kn = 0.0;  // c_t = c_n sqrt(k_t / k_n)
  };

  // The seed's eqs. 1-2: k_n, and k_t (k_n / 2 when only k_n is given, as the seed's Table 2).
  static constexpr std::array<LawParameter, 2> parameters{{
      {"normal_stiffness", &ContactLaw::normal_stiffness, "N/m", open_closed(0.0, kMaxLawStiffness), "a positive stiffness",
       {}, 1.0, false, true},
      {"tangential_stiffness", &ContactLaw::tangential_stiffness, "N/m", closed(0.0, kMaxLawStiffness), "a stiffness >= 0",
       "normal_stiffness", 0.5, false, true},
  }};
  // What sets the contact's stiffness (parameters[stiffness_parameter]), in words; whether the
  // contact reads the other body's material too (no: k_n is the law's own); the time scale's formula.
  static constexpr std::size_t stiffness_parameter = 0;
  static constexpr std::string_view stiffness_name = "normal stiffness";
  static constexpr bool combines_materials = false;
  static constexpr std::string_view time_scale_formula = "sqrt(m_min/k_max)";

  static Params params(const ContactLaw& law, const ContactLaw& /*particle_law*/) {
    return {law.normal_stiffness, law.tangential_stiffness, std::sqrt(law.tangential_stiffness / law.normal_stiffness)};
  }

  [[gnu::always_inline]] static NormalResponse respond(const Params& p, double overlap, double /*effective_radius*/) {
    return {p.kn * overlap, p.kn, p.kn, p.kt, p.sqrt_kt_over_kn};
  }

  // sqrt(m / k_n), the characteristic period of the contact of a particle of mass m (kg) with a
  // body of infinite mass. The central-difference limit for one spring is 2 sqrt(m/k); DEM
  // practice runs at 0.1-0.2 of sqrt(m/k) (Otsubo et al. 2017).
  static double time_scale(const ContactLaw& law, const ContactLaw& /*particle_law*/, double mass, double /*radius*/) {
    return std::sqrt(mass / law.normal_stiffness);
  }
};

}  // namespace trapdem
