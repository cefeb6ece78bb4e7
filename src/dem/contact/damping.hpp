#pragma once
// Restitution-based viscous damping: the normal dashpot c_n = f beta sqrt(m* S_n), with
// beta = -ln e / sqrt(ln^2 e + pi^2) and f = 2 x the normal model's damping_scale: f = 2 for the
// linear spring (the seed paper's eq. 1, which gives e exactly), f = 2 sqrt(5/6) for Hertz (Tsuji
// et al. 1992, as in LIGGGHTS). The tangential dashpot is c_t = c_n sqrt(S_t / S_n).

#include <array>
#include <cmath>

#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"

namespace trapdem {

struct RestitutionDamping {
  // e, which sets both dashpots (damping_model adjusts it: ContactLaw::damping_restitution).
  static constexpr std::array<LawParameter, 1> parameters{{
      {"restitution", &ContactLaw::restitution, "", open_closed(0.0, 1.0), "a coefficient of restitution in (0, 1]"},
  }};

  struct Params {
    double factor = 0.0;  // f beta (dimensionless)
  };

  // N s/m, the normal dashpot of a contact of effective mass m* (kg) and normal stiffness S_n (N/m).
  [[gnu::always_inline]] static double normal_coefficient(const Params& p, double effective_mass,
                                                          double damping_stiffness) {
    return p.factor * std::sqrt(effective_mass * damping_stiffness);
  }
};

}  // namespace trapdem
