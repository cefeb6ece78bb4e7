#pragma once
// Rolling resistance, Ai et al. (2011) type A: a constant torque M = mu_r R |F_n| against the
// relative rolling (the seed paper's eq. 5).
#include <algorithm>
#include <cmath>

#include "dem/vec3.hpp"

namespace trapdem {

struct ConstantTorqueRolling {
  // The torque on body i for the relative rolling velocity wr (rad/s, in the tangent plane) and
  // the limit m_max = mu_r R |F_n| (N m). Bounded by what stops the relative rolling within one
  // step (spin_inertia wr / dt), so that a sphere at rest does not chatter.
  [[gnu::always_inline]] static Vec3 torque(const Vec3& wr, double m_max, double spin_inertia, double dt) {
    Vec3 rolling_torque{};
    const double wr_len = norm(wr);
    if (wr_len > 0.0) {
      const double m = std::min(m_max, spin_inertia * wr_len / dt);
      rolling_torque = wr * (-m / wr_len);
    }
    return rolling_torque;
  }
};

}  // namespace trapdem
