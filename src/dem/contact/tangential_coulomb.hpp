#pragma once
// Tangential force: an incremental spring-dashpot (the seed paper's eq. 2) capped by static and
// kinetic Coulomb friction. Its stiffness comes from the normal model (constant k_t for the
// linear spring, Mindlin's 8 G* a for Hertz).
#include <array>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/contact/tangential_spring.hpp"
#include "dem/contact/law_parameter.hpp"
#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct CoulombTangential {
  static constexpr TangentialModel model = TangentialModel::coulomb;
  static constexpr bool needs_tangential_mass = false;
  static constexpr bool carries_spring_force = true;  // F_t = -k_t s at rest (element_stress.cpp)
  struct Params {
    double mu_s = 0.0;  // the stick limit |F_t| <= mu_s |F_n|
    double mu_k = 0.0;  // |F_t| = mu_k |F_n| while sliding
  };
  // mu_s and mu_k (mu_k = mu_s when only mu_s is given).
  static constexpr std::array<LawParameter, 2> parameters{{
      {"static_friction", &ContactLaw::static_friction, "", closed(0.0, kMaxLawFriction), "a friction coefficient >= 0"},
      {"kinetic_friction", &ContactLaw::kinetic_friction, "", closed(0.0, kMaxLawFriction), "a friction coefficient >= 0",
       "static_friction", 1.0},
  }};
  static Params params(const ContactLaw& law) { return {law.static_friction, law.kinetic_friction}; }

  // The tangential force on body i; updates the history's spring (the evaluator sets the flags
  // from the returned `sliding`).
  [[gnu::always_inline]] static TangentialResponse force(const Params& p, ContactHistory& h, const TangentialInputs& in) {
    const Vec3& n = in.normal;
    const Vec3& vt = in.slip_velocity;
    const double kt = in.stiffness, c_t = in.dashpot, fn_abs = in.normal_force;
    Vec3 s = advanced_spring(h.tangential_spring, n, vt, in.dt);
    Vec3 ft = -kt * s - c_t * vt;

    // Sticking holds while |F_t| <= mu_s |F_n|; beyond it the contact slides, and a sliding
    // contact carries at most mu_k |F_n|: the trial force is cut back to that cone, never raised
    // to it (raising it would stretch the spring and feed energy in). It sticks again once the
    // trial force lies inside the kinetic cone (the spring unloads). With mu_k < mu_s a yielding
    // contact drops from mu_s to mu_k |F_n|. With mu_k > mu_s (the paper's Table 2) a contact past
    // mu_s |F_n| is marked sliding but keeps its elastic force up to mu_k |F_n|: it carries at
    // most mu_k |F_n|, and mu_s changes no force.
    // Written as selects rather than nested branches, so that the batch loops vectorise.
    const double ft2 = norm2(ft);
    const double kinetic_limit2 = p.mu_k * p.mu_k * fn_abs * fn_abs;
    const bool sliding = ft2 > (h.sliding() ? kinetic_limit2 : p.mu_s * p.mu_s * fn_abs * fn_abs);
    if (sliding && ft2 > kinetic_limit2) {
      ft *= p.mu_k * fn_abs / std::sqrt(ft2);
      // The spring keeps what the dashpot does not carry, so that F_t is continuous when it sticks again.
      s = kt > 0.0 ? -(ft + c_t * vt) / kt : Vec3{};
    }
    h.tangential_spring = s;
    return {ft, sliding};
  }
};

}  // namespace trapdem
