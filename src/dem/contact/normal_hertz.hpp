#pragma once
// Hertz normal contact with Mindlin's no-slip tangential stiffness, from the bodies' Young's
// moduli and Poisson's ratios (Johnson, Contact Mechanics, 1985, sections 4.2 and 7.2; the form of
// LIGGGHTS's "model hertz" and LAMMPS's "hertz/material" with "tangential mindlin"):
//   a = sqrt(R* delta)                       contact radius
//   F_n = 4/3 E* a delta                     (= 4/3 E* sqrt(R*) delta^3/2)
//   S_n = dF_n/d(delta) = 2 E* a             normal contact stiffness
//   k_t = S_t = 8 G* a                       Mindlin's tangential stiffness
//   1/E* = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j
//   1/G* = 2 (2 - nu_i)(1 + nu_i)/E_i + 2 (2 - nu_j)(1 + nu_j)/E_j   (LAMMPS pair_granular, mindlin)
// The dashpots follow Tsuji et al. (1992) as LIGGGHTS writes them:
// c_n = 2 sqrt(5/6) beta sqrt(S_n m*), c_t = 2 sqrt(5/6) beta sqrt(S_t m*) (damping.hpp).
// A particle-wall contact combines the particle's material (the particle law's E, nu) with the
// wall's (the wall law's); a particle pair has the particle material on both sides.
#include <array>
#include <cstddef>
#include <string_view>
#include <cmath>
#include <numbers>

#include "dem/contact/choices.hpp"
#include "dem/contact/normal_response.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"

namespace trapdem {

struct NormalHertz {
  static constexpr NormalModel model = NormalModel::hertz;
  // sqrt(5/6): Tsuji et al. (1992) / LIGGGHTS normal_model_hertz, c_n = 2 sqrt(5/6) beta sqrt(S_n m*).
  static constexpr double damping_scale = 0.91287092917527685576;

  struct Params {
    double e_star = 0.0;                 // Pa, effective Young's modulus E*
    double g_star = 0.0;                 // Pa, effective shear modulus G*
    double sqrt_st_over_sn = 0.0;        // sqrt(S_t / S_n) = sqrt(4 G* / E*)
  };

  // What sets the contact's stiffness (parameters[stiffness_parameter]), in words; the contact
  // combines both bodies' E and nu (a wall's Hertz law reads the particles' material); the time
  // scale's formula.
  static constexpr std::size_t stiffness_parameter = 0;
  static constexpr std::string_view stiffness_name = "Young's modulus";
  static constexpr bool combines_materials = true;
  static constexpr std::string_view time_scale_formula = "the Rayleigh time T_R";

  // E* and G* of the contact under `law` (the wall's for a wall law) with the particle material.
  // The material's E and nu: read with any normal model (another law's Hertz contact with this
  // body reads them), required with this one.
  static constexpr std::array<LawParameter, 2> parameters{{
      {"youngs_modulus", &ContactLaw::youngs_modulus, "Pa", open_closed(0.0, kMaxLawModulus),
       "a positive Young's modulus (the Hertz normal model needs it)", {}, 1.0, true},
      {"poisson_ratio", &ContactLaw::poisson_ratio, "", closed_open(0.0, 0.5), "a Poisson's ratio", {}, 1.0, true},
  }};
  static Params params(const ContactLaw& law, const ContactLaw& particle_law) {
    const double e1 = particle_law.youngs_modulus, nu1 = particle_law.poisson_ratio;
    const double e2 = law.youngs_modulus, nu2 = law.poisson_ratio;
    Params p;
    p.e_star = 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
    p.g_star = 1.0 / (2.0 * (2.0 - nu1) * (1.0 + nu1) / e1 + 2.0 * (2.0 - nu2) * (1.0 + nu2) / e2);
    p.sqrt_st_over_sn = std::sqrt(4.0 * p.g_star / p.e_star);
    return p;
  }

  [[gnu::always_inline]] static NormalResponse respond(const Params& p, double overlap, double effective_radius) {
    const double a = std::sqrt(effective_radius * overlap);  // m, contact radius
    const double kn = (4.0 / 3.0) * p.e_star * a;
    return {kn * overlap, kn, 2.0 * p.e_star * a, 8.0 * p.g_star * a, p.sqrt_st_over_sn};
  }

  // The Rayleigh time of the particle material, T_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766)
  // (the time a Rayleigh wave takes across the particle; Li, Xu & Thornton 2005; LIGGGHTS's
  // fix check/timestep/gran warns above 0.2 T_R). Chosen over the Hertz contact time
  // t_c = 2.87 (m*^2 / (R* E*^2 v))^1/5 because that one depends on the impact velocity v, unknown
  // before the run, while T_R bounds the step for any impact. The particle's density comes from
  // its mass and radius; G = E / (2 (1 + nu)) of the particle law's material.
  static double time_scale(const ContactLaw& /*law*/, const ContactLaw& particle_law, double mass, double radius) {
    const double density = mass / (4.0 / 3.0 * std::numbers::pi * radius * radius * radius);
    const double nu = particle_law.poisson_ratio;
    const double shear_modulus = particle_law.youngs_modulus / (2.0 * (1.0 + nu));
    return std::numbers::pi * radius * std::sqrt(density / shear_modulus) / (0.1631 * nu + 0.8766);
  }
};

}  // namespace trapdem
