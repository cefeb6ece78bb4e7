#pragma once
// The contact law, written once for particle-particle and particle-wall contacts.
// A free function on plain values so that any back end (OpenMP loop now, GPU or MPI later)
// can call it unchanged. The pair and wall kernels call it inside loops over batches of contacts
// that the compiler vectorises (PairBatchLaw in simulation.cpp, WallBatchLaw in contact_batch.hpp):
// its branches on per-contact values must stay if-convertible (selects, no loads or stores of
// memory under them).
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// What a contact remembers between steps. Owned by the pair (neighbour list) or by the
// particle-wall candidate; expressed for side i (a flipped pair negates the vectors).
struct ContactHistory {
  Vec3 tangential_spring;     // m, accumulated tangential displacement (eq. 2's integral)
  Vec3 rolling_spring;        // N m, elastic rolling torque of the EPSD model
  std::uint32_t flags = 0;    // kTouching | kSliding

  static constexpr std::uint32_t kTouching = 1u;
  static constexpr std::uint32_t kSliding = 2u;
  bool touching() const { return flags & kTouching; }
  bool sliding() const { return flags & kSliding; }
  void reset() { *this = ContactHistory{}; }
};

// The two bodies as the law sees them.
struct ContactBodies {
  double effective_mass;     // kg, m_i m_j / (m_i + m_j); m_i at a wall
  double arm_i, arm_j;       // m, centre to contact point (0 for a wall)
  double lever;              // m, rolling lever arm R
  double rolling_inertia;    // kg m^2, Ai et al. (2011) I_r = [1/(I_i + m_i r_i^2) + 1/(I_j + m_j r_j^2)]^-1
  double spin_inertia;       // kg m^2, [1/I_i + 1/I_j]^-1, bounds the constant torque (see below)
};

struct ContactForce {
  Vec3 force;                // N, on body i (body j receives -force)
  Vec3 tangential;           // N, the tangential part of force (for the torques r x F_t)
  Vec3 rolling_torque;       // N m, on body i (body j receives -rolling_torque)
  double normal_force;       // N, signed: positive when repulsive
};

// normal: unit vector from body j towards body i; overlap > 0 (m);
// relative_velocity: v_i - v_j of the centres (m/s); w_i, w_j angular velocities (rad/s).
[[gnu::always_inline]] inline ContactForce contact_force(const ContactConstants& c, const ContactBodies& b, const Vec3& normal,
                                  double overlap, const Vec3& relative_velocity, const Vec3& w_i,
                                  const Vec3& w_j, ContactHistory& h, double dt) {
  const Vec3& n = normal;
  // Relative velocity of the contact points: v_i + w_i x (-a_i n) - (v_j + w_j x (a_j n)).
  const Vec3 v = relative_velocity - cross(b.arm_i * w_i + b.arm_j * w_j, n);
  const double vn = dot(v, n);
  const Vec3 vt = v - vn * n;

  // Seed eq. 1: F_n = k_n delta - c_n v_n, c_n = 2 beta sqrt(m* k_n). Not clamped at zero: the
  // dashpot may pull briefly as a collision ends, which is what makes e come out as set.
  const double c_n = c.two_beta * std::sqrt(b.effective_mass * c.kn);
  const double fn = c.kn * overlap - c_n * vn;
  const double fn_abs = std::fabs(fn);

  // Seed eq. 2: incremental tangential spring, first turned into the current tangent plane
  // with its length kept (the contact has rotated since the last step).
  // The contact turns by a tiny angle per step in a dense, slow packing; when the spring's
  // out-of-plane part x = (s.n)^2 / |s|^2 is below 1e-12 the rescaling 1 / sqrt(1 - x) differs
  // from 1 by less than 5e-13, and the square root and division (a sixth of the pair loop's
  // time) are skipped.
  Vec3 s = h.tangential_spring;
  const double s2 = norm2(s);
  const double sn = dot(s, n);
  const double sn2 = sn * sn;
  if (sn2 > 1e-12 * s2) {
    const Vec3 in_plane = s - sn * n;
    const double p2 = norm2(in_plane);
    s = p2 > 0.0 ? in_plane * std::sqrt(s2 / p2) : Vec3{};
  } else {
    s -= sn * n;
  }
  s += vt * dt;
  const double c_t = c_n * c.sqrt_kt_over_kn;  // 2 beta sqrt(m* k_t)
  Vec3 ft = -c.kt * s - c_t * vt;

  // Static/kinetic Coulomb friction. Sticking holds while |F_t| <= mu_s |F_n|; beyond it the
  // contact slides, and a sliding contact carries at most mu_k |F_n|: the trial force is cut back
  // to that cone, never raised to it (raising it would stretch the spring and feed energy in). It
  // sticks again once the trial force lies inside the kinetic cone (the spring unloads).
  // With mu_k < mu_s a yielding contact drops from mu_s to mu_k |F_n|. With mu_k > mu_s (the
  // paper's Table 2) a contact past mu_s |F_n| is marked sliding but keeps its elastic force up
  // to mu_k |F_n|: it carries at most mu_k |F_n|, and mu_s changes no force.
  // Written as selects rather than nested branches, so that the batch loop over contacts
  // (simulation.cpp) can be vectorised.
  const double ft2 = norm2(ft);
  const double kinetic_limit2 = c.mu_k * c.mu_k * fn_abs * fn_abs;
  const bool sliding = ft2 > (h.sliding() ? kinetic_limit2 : c.mu_s * c.mu_s * fn_abs * fn_abs);
  if (sliding && ft2 > kinetic_limit2) {
    ft *= c.mu_k * fn_abs / std::sqrt(ft2);
    // The spring keeps what the dashpot does not carry, so that F_t is continuous when it sticks again.
    s = c.kt > 0.0 ? -(ft + c_t * vt) / c.kt : Vec3{};
  }
  h.tangential_spring = s;
  h.flags = ContactHistory::kTouching | (sliding ? ContactHistory::kSliding : 0u);

  Vec3 rolling_torque{};
  if (c.rolling != 0) {
    // Relative rolling: the relative angular velocity less its twist about the normal.
    Vec3 wr = w_i - w_j;
    wr -= dot(wr, n) * n;
    const double m_max = c.mu_r * b.lever * fn_abs;  // seed eq. 5
    if (c.rolling == 1) {
      // Type A: constant torque against the relative rolling. Bounded by what stops the
      // relative rolling within one step, so that a sphere at rest does not chatter.
      const double wr_len = norm(wr);
      if (wr_len > 0.0) {
        const double m = std::min(m_max, b.spin_inertia * wr_len / dt);
        rolling_torque = wr * (-m / wr_len);
      }
    } else {
      // Type C (EPSD), Ai et al. (2011) eqs. 14-18.
      const double kr = c.rolling_stiffness_from_kt ? c.kt * b.lever * b.lever
                                                    : 2.25 * c.kn * c.mu_r * c.mu_r * b.lever * b.lever;
      Vec3 mk = h.rolling_spring;
      mk -= dot(mk, n) * n;
      mk -= kr * dt * wr;
      const double mk2 = norm2(mk);
      if (mk2 > m_max * m_max) {
        mk *= m_max / std::sqrt(mk2);  // fully mobilised: no dashpot (Ai et al. eq. 18)
        rolling_torque = mk;
      } else {
        rolling_torque = mk;
        if (c.needs_rolling_inertia) rolling_torque -= (c.eta_r * 2.0 * std::sqrt(b.rolling_inertia * kr)) * wr;
      }
      h.rolling_spring = mk;
    }
  }
  return {fn * n + ft, ft, rolling_torque, fn};
}

}  // namespace trapdem
