#include "dem/rigid/free_rotation.hpp"

#include <algorithm>
#include <cmath>

namespace trapdem {

namespace {

// sin and cos of a sub-rotation's angle. A step turns a grain by w dt ~ 1e-5 rad, where the Taylor
// series to the 7th (sin) and 8th (cos) power are exact in double precision (the first term left
// out is below 3e-22 of the result for |t| < 0.01) at a fraction of the cost of sincos, which took a
// quarter of a clump bed's step; beyond 0.01 rad, the library's.
void step_sincos(double t, double& s, double& c) {
  if (std::abs(t) < 1e-2) {
    // Multiplications by the reciprocals (a division each would cost as much as the rest).
    constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0;
    constexpr double k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0;
    const double t2 = t * t;
    s = t * (1.0 - t2 * k6 * (1.0 - t2 * k20 * (1.0 - t2 * k42)));
    c = 1.0 - 0.5 * t2 * (1.0 - t2 * k12 * (1.0 - t2 * k30 * (1.0 - t2 * k56)));
  } else {
    s = std::sin(t);
    c = std::cos(t);
  }
}

// R_k(h): the body turns by theta = h L_k / I_k about its own axis k; seen from the body, the
// (fixed) space-frame angular momentum turns by -theta about that axis.
// The axis is a template argument: the components it picks are fixed at compile time.
template <int k>
[[gnu::always_inline]] inline void rotate_about_body_axis(Quaternion& q, Vec3& L, const Vec3& inverse_inertia, double h) {
  const double theta = h * L[k] * inverse_inertia[k];
  double half_s, half_c;
  step_sincos(0.5 * theta, half_s, half_c);
  // q <- q (cos(theta/2), sin(theta/2) e_k): the Hamilton product with a turn about one axis.
  const Quaternion p = q;
  if constexpr (k == 0) {
    q = {p.w * half_c - p.x * half_s, p.x * half_c + p.w * half_s, p.y * half_c + p.z * half_s, p.z * half_c - p.y * half_s};
  } else if constexpr (k == 1) {
    q = {p.w * half_c - p.y * half_s, p.x * half_c - p.z * half_s, p.y * half_c + p.w * half_s, p.z * half_c + p.x * half_s};
  } else {
    q = {p.w * half_c - p.z * half_s, p.x * half_c + p.y * half_s, p.y * half_c - p.x * half_s, p.z * half_c + p.w * half_s};
  }
  double s, c;
  step_sincos(theta, s, c);
  constexpr int a = (k + 1) % 3, b = (k + 2) % 3;  // L_body <- R_k(-theta) L_body
  const double La = L[a], Lb = L[b];
  L[a] = c * La + s * Lb;
  L[b] = -s * La + c * Lb;
}

}  // namespace

void rotate_freely(Quaternion& q, Vec3& momentum_body, const Vec3& inertia, double dt) {
  // Miller et al. (2002): the symmetric splitting, the third axis outermost.
  // A zero moment (a body without extent about an axis) does not turn about that axis.
  const Vec3 inverse{inertia.x > 0.0 ? 1.0 / inertia.x : 0.0, inertia.y > 0.0 ? 1.0 / inertia.y : 0.0,
                     inertia.z > 0.0 ? 1.0 / inertia.z : 0.0};
  rotate_about_body_axis<2>(q, momentum_body, inverse, 0.5 * dt);
  rotate_about_body_axis<1>(q, momentum_body, inverse, 0.5 * dt);
  rotate_about_body_axis<0>(q, momentum_body, inverse, dt);
  rotate_about_body_axis<1>(q, momentum_body, inverse, 0.5 * dt);
  rotate_about_body_axis<2>(q, momentum_body, inverse, 0.5 * dt);
  // Renormalised against round-off: one division, the rest multiplications.
  const double scale = 1.0 / std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  q = {q.w * scale, q.x * scale, q.y * scale, q.z * scale};
}

namespace {

// Series sin and cos, valid for |t| < 0.01 (step_sincos), without the branch: for the lanes.
[[gnu::always_inline]] inline void series_sincos(double t, double& s, double& c) {
  constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0;
  constexpr double k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0;
  const double t2 = t * t;
  s = t * (1.0 - t2 * k6 * (1.0 - t2 * k20 * (1.0 - t2 * k42)));
  c = 1.0 - 0.5 * t2 * (1.0 - t2 * k12 * (1.0 - t2 * k30 * (1.0 - t2 * k56)));
}

// The lanes' state, one array per component (structure of arrays: one SIMD register each).
struct Lanes {
  double w[kRotationLanes], x[kRotationLanes], y[kRotationLanes], z[kRotationLanes];
  double l[3][kRotationLanes];        // the angular momentum, body frame
  double inverse[3][kRotationLanes];  // 1 / principal moment (0: none)
};

// rotate_about_body_axis<k> for every lane.
template <int k>
[[gnu::always_inline]] inline void rotate_lanes_about(Lanes& s, double h) {
  constexpr int a = (k + 1) % 3, b = (k + 2) % 3;
#pragma omp simd
  for (int n = 0; n < kRotationLanes; ++n) {
    const double theta = h * s.l[k][n] * s.inverse[k][n];
    double hs, hc, sn, cs;
    series_sincos(0.5 * theta, hs, hc);
    series_sincos(theta, sn, cs);
    const double w = s.w[n], x = s.x[n], y = s.y[n], z = s.z[n];
    if constexpr (k == 0) {
      s.w[n] = w * hc - x * hs; s.x[n] = x * hc + w * hs; s.y[n] = y * hc + z * hs; s.z[n] = z * hc - y * hs;
    } else if constexpr (k == 1) {
      s.w[n] = w * hc - y * hs; s.x[n] = x * hc - z * hs; s.y[n] = y * hc + w * hs; s.z[n] = z * hc + x * hs;
    } else {
      s.w[n] = w * hc - z * hs; s.x[n] = x * hc + y * hs; s.y[n] = y * hc - x * hs; s.z[n] = z * hc + w * hs;
    }
    const double la = s.l[a][n], lb = s.l[b][n];
    s.l[a][n] = cs * la + sn * lb;
    s.l[b][n] = -sn * la + cs * lb;
  }
}

}  // namespace

void rotate_freely_lanes(Quaternion* q, Vec3* momentum_body, const Vec3* inertia, double dt, int count) {
  Lanes s{};
  int lanes = 0;
  int alone[kRotationLanes];  // the bodies that turn too far for the series: rotate_freely
  int alone_count = 0;
  for (int n = 0; n < count; ++n) {
    const Vec3& I = inertia[n];
    const Vec3 inverse{I.x > 0.0 ? 1.0 / I.x : 0.0, I.y > 0.0 ? 1.0 / I.y : 0.0, I.z > 0.0 ? 1.0 / I.z : 0.0};
    // Every sub-rotation's angle is at most dt |L| / I_k (the body-frame components of L turn, its
    // length does not).
    const double largest = dt * norm(momentum_body[n]) * std::max({inverse.x, inverse.y, inverse.z});
    if (!(largest < 1e-2)) {
      alone[alone_count++] = n;
      continue;
    }
    s.w[lanes] = q[n].w; s.x[lanes] = q[n].x; s.y[lanes] = q[n].y; s.z[lanes] = q[n].z;
    for (int k = 0; k < 3; ++k) {
      s.l[k][lanes] = momentum_body[n][k];
      s.inverse[k][lanes] = inverse[k];
    }
    ++lanes;
  }
  // Unused lanes turn nothing (zero momentum, unit quaternion): harmless, and never read back.
  for (int n = lanes; n < kRotationLanes; ++n) s.w[n] = 1.0;
  rotate_lanes_about<2>(s, 0.5 * dt);
  rotate_lanes_about<1>(s, 0.5 * dt);
  rotate_lanes_about<0>(s, dt);
  rotate_lanes_about<1>(s, 0.5 * dt);
  rotate_lanes_about<2>(s, 0.5 * dt);
  int lane = 0;
  for (int n = 0, next_alone = 0; n < count; ++n) {
    if (next_alone < alone_count && alone[next_alone] == n) {
      ++next_alone;
      rotate_freely(q[n], momentum_body[n], inertia[n], dt);
      continue;
    }
    const double scale = 1.0 / std::sqrt(s.w[lane] * s.w[lane] + s.x[lane] * s.x[lane] + s.y[lane] * s.y[lane] +
                                         s.z[lane] * s.z[lane]);
    q[n] = {s.w[lane] * scale, s.x[lane] * scale, s.y[lane] * scale, s.z[lane] * scale};
    momentum_body[n] = {s.l[0][lane], s.l[1][lane], s.l[2][lane]};
    ++lane;
  }
}

Vec3 angular_velocity_space(const Quaternion& q, const Vec3& L, const Vec3& inertia) {
  return rotate(q, Vec3{L.x / inertia.x, L.y / inertia.y, L.z / inertia.z});
}

}  // namespace trapdem
