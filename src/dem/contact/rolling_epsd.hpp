#pragma once
// Rolling resistance, Ai et al. (2011) type C (elastic-plastic spring-dashpot, EPSD), eqs. 14-18:
// an incremental spring torque capped at mu_r R |F_n|, with a dashpot while it is below the cap.
#include <cmath>

#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

struct EpsdRolling {
  // The torque on body i for the normal n, relative rolling velocity wr (rad/s), rolling
  // friction mu_r, limit m_max = mu_r R |F_n| (N m), lever R (m), the normal model's k_n and k_t
  // (N/m), the dashpot's damping ratio eta_r (Ai et al. 2011 use 0.3) and the rolling inertia
  // (kg m^2); updates the history's rolling spring.
  template <RollingStiffness kStiffness, bool kDashpot>
  [[gnu::always_inline]] static Vec3 torque(ContactHistory& h, const Vec3& n, const Vec3& wr, double mu_r,
                                            double m_max, double lever, double kn, double kt, double eta_r,
                                            double rolling_inertia, double dt) {
    const double kr = kStiffness == RollingStiffness::tangential ? kt * lever * lever
                                                                 : 2.25 * kn * mu_r * mu_r * lever * lever;
    Vec3 mk = h.rolling_spring;
    mk -= dot(mk, n) * n;
    mk -= kr * dt * wr;
    const double mk2 = norm2(mk);
    Vec3 rolling_torque;
    if (mk2 > m_max * m_max) {
      mk *= m_max / std::sqrt(mk2);  // fully mobilised: no dashpot (Ai et al. eq. 18)
      rolling_torque = mk;
    } else {
      rolling_torque = mk;
      if (kDashpot) rolling_torque -= (eta_r * 2.0 * std::sqrt(rolling_inertia * kr)) * wr;
    }
    h.rolling_spring = mk;
    return rolling_torque;
  }
};

}  // namespace trapdem
