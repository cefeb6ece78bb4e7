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

// The symmetric top's exact step (free_rotation.hpp) with the library's sin and cos: any angle.
void rotate_symmetric_top(Quaternion& q, Vec3& L, const Vec3& inertia, int axis, double dt) {
  const double perpendicular = inertia[(axis + 1) % 3];
  const double length = norm(L);
  // q <- q (cos(psi/2), sin(psi/2) L/|L|), psi = dt |L| / I_perp: the precession about L, in the body frame.
  if (length > 0.0) {
    const double half_psi = 0.5 * dt * length / perpendicular;
    const double s = std::sin(half_psi) / length;
    q = q * Quaternion{std::cos(half_psi), s * L.x, s * L.y, s * L.z};
  }
  // q <- q (cos(phi/2), sin(phi/2) e_axis), phi = dt L_axis (1/I_axis - 1/I_perp): the spin about
  // the symmetry axis relative to the precession; L's body components turn by -phi about it.
  const double phi = dt * L[axis] * (1.0 / inertia[axis] - 1.0 / perpendicular);
  Quaternion turn{std::cos(0.5 * phi), 0.0, 0.0, 0.0};
  (axis == 0 ? turn.x : axis == 1 ? turn.y : turn.z) = std::sin(0.5 * phi);
  q = normalised(q * turn);
  const int a = (axis + 1) % 3, b = (axis + 2) % 3;
  const double c = std::cos(phi), sn = std::sin(phi), La = L[a], Lb = L[b];
  L[a] = c * La + sn * Lb;
  L[b] = -sn * La + c * Lb;
}

}  // namespace

int symmetry_axis(const Vec3& I) {
  if (I.y == I.z) return 0;  // prolate (a dimer) or spherical
  if (I.x == I.y) return 2;  // oblate
  if (I.x == I.z) return 1;  // moments not in ascending order
  return -1;
}

namespace {

// The symmetric top's axis when the body turns as one (every moment positive), else -1: the
// integrator rotate_freely and the lanes choose by it alike.
int top_axis(const Vec3& I) { return I.x > 0.0 && I.y > 0.0 && I.z > 0.0 ? symmetry_axis(I) : -1; }

}  // namespace

void rotate_freely(Quaternion& q, Vec3& momentum_body, const Vec3& inertia, double dt) {
  const int axis = top_axis(inertia);
  if (axis >= 0) {
    rotate_symmetric_top(q, momentum_body, inertia, axis, dt);
    return;
  }
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

// The symmetric top's exact step (rotate_symmetric_top) for every lane, `axis` the odd moment's:
// the precession about L by psi = dt |L| / I_perp, then the spin about the axis by phi = dt L_axis
// (1/I_axis - 1/I_perp). The series need only |L|^2 (sin(psi/2) / |L| = (dt / 2 I_perp) sinc):
// no square root, no division. Two turns instead of NO_SQUISH's five.
template <int axis>
[[gnu::always_inline]] inline void rotate_top_lanes(Lanes& s, double dt) {
  constexpr int a = (axis + 1) % 3, b = (axis + 2) % 3;
  constexpr double k6 = 1.0 / 6.0, k20 = 1.0 / 20.0, k42 = 1.0 / 42.0;
  constexpr double k12 = 1.0 / 12.0, k30 = 1.0 / 30.0, k56 = 1.0 / 56.0;
#pragma omp simd
  for (int n = 0; n < kRotationLanes; ++n) {
    const double lx = s.l[0][n], ly = s.l[1][n], lz = s.l[2][n];
    const double k = 0.5 * dt * s.inverse[a][n];  // psi / 2 = k |L|
    const double t2 = k * k * (lx * lx + ly * ly + lz * lz);
    const double f = k * (1.0 - t2 * k6 * (1.0 - t2 * k20 * (1.0 - t2 * k42)));   // sin(psi/2) / |L|
    const double pw = 1.0 - 0.5 * t2 * (1.0 - t2 * k12 * (1.0 - t2 * k30 * (1.0 - t2 * k56)));  // cos(psi/2)
    const double px = f * lx, py = f * ly, pz = f * lz;
    double w = s.w[n], x = s.x[n], y = s.y[n], z = s.z[n];
    // q <- q (pw, p): the Hamilton product.
    const double w1 = w * pw - x * px - y * py - z * pz, x1 = w * px + x * pw + y * pz - z * py,
                 y1 = w * py - x * pz + y * pw + z * px, z1 = w * pz + x * py - y * px + z * pw;
    double hs, hc;
    series_sincos(0.5 * dt * s.l[axis][n] * (s.inverse[axis][n] - s.inverse[a][n]), hs, hc);
    if constexpr (axis == 0) {
      w = w1 * hc - x1 * hs; x = x1 * hc + w1 * hs; y = y1 * hc + z1 * hs; z = z1 * hc - y1 * hs;
    } else if constexpr (axis == 1) {
      w = w1 * hc - y1 * hs; x = x1 * hc - z1 * hs; y = y1 * hc + w1 * hs; z = z1 * hc + x1 * hs;
    } else {
      w = w1 * hc - z1 * hs; x = x1 * hc + y1 * hs; y = y1 * hc - x1 * hs; z = z1 * hc + w1 * hs;
    }
    s.w[n] = w; s.x[n] = x; s.y[n] = y; s.z[n] = z;
    // L's body components turn by -phi about the axis (sin and cos of phi from the half angle's).
    const double sn = 2.0 * hs * hc, cs = 1.0 - 2.0 * hs * hs;
    const double la = s.l[a][n], lb = s.l[b][n];
    s.l[a][n] = cs * la + sn * lb;
    s.l[b][n] = -sn * la + cs * lb;
  }
}

}  // namespace

void rotate_freely_lanes(Quaternion* q, Vec3* momentum_body, const Vec3* inertia, double dt, int count) {
  // Lane n holds body n. The inverses, the check of the angles and the renormalisation run over the
  // lanes side by side (a division and a square root each, which one body at a time would wait on);
  // a body the lanes must not turn is turned afterwards by rotate_freely from its unchanged state.
  Lanes s{};
  const int lanes_axis = count > 0 ? top_axis(inertia[0]) : -1;  // the lanes' kind: a top's axis, or -1
  bool own_kind[kRotationLanes] = {};
  for (int n = 0; n < count; ++n) {
    s.w[n] = q[n].w; s.x[n] = q[n].x; s.y[n] = q[n].y; s.z[n] = q[n].z;
    for (int k = 0; k < 3; ++k) {
      s.l[k][n] = momentum_body[n][k];
      s.inverse[k][n] = inertia[n][k];
    }
    own_kind[n] = top_axis(inertia[n]) == lanes_axis;
  }
  // Unused lanes turn nothing (zero momentum, unit quaternion, no inverse): harmless, never read back.
  for (int n = count; n < kRotationLanes; ++n) s.w[n] = 1.0;
  double within_series[kRotationLanes];  // 1: every sub-rotation's angle below 0.01 rad
#pragma omp simd
  for (int n = 0; n < kRotationLanes; ++n) {
    double largest = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double I = s.inverse[k][n];
      s.inverse[k][n] = I > 0.0 ? 1.0 / I : 0.0;  // a zero moment does not turn about its axis
      largest = std::max(largest, s.inverse[k][n]);
    }
    // Every sub-rotation's angle is at most dt |L| / I_k (the body-frame components of L turn, its
    // length does not).
    const double l2 = s.l[0][n] * s.l[0][n] + s.l[1][n] * s.l[1][n] + s.l[2][n] * s.l[2][n];
    within_series[n] = dt * dt * l2 * largest * largest < 1e-4 ? 1.0 : 0.0;  // false for NaN too
  }
  switch (lanes_axis) {
    case 0: rotate_top_lanes<0>(s, dt); break;
    case 1: rotate_top_lanes<1>(s, dt); break;
    case 2: rotate_top_lanes<2>(s, dt); break;
    default:  // NO_SQUISH, as rotate_freely
      rotate_lanes_about<2>(s, 0.5 * dt);
      rotate_lanes_about<1>(s, 0.5 * dt);
      rotate_lanes_about<0>(s, dt);
      rotate_lanes_about<1>(s, 0.5 * dt);
      rotate_lanes_about<2>(s, 0.5 * dt);
  }
#pragma omp simd
  for (int n = 0; n < kRotationLanes; ++n) {  // renormalised against round-off
    const double scale = 1.0 / std::sqrt(s.w[n] * s.w[n] + s.x[n] * s.x[n] + s.y[n] * s.y[n] + s.z[n] * s.z[n]);
    s.w[n] *= scale; s.x[n] *= scale; s.y[n] *= scale; s.z[n] *= scale;
  }
  for (int n = 0; n < count; ++n) {
    if (!own_kind[n] || within_series[n] == 0.0) {
      rotate_freely(q[n], momentum_body[n], inertia[n], dt);
      continue;
    }
    q[n] = {s.w[n], s.x[n], s.y[n], s.z[n]};
    momentum_body[n] = {s.l[0][n], s.l[1][n], s.l[2][n]};
  }
}

Vec3 angular_velocity_space(const Quaternion& q, const Vec3& L, const Vec3& inertia) {
  return rotate(q, Vec3{L.x / inertia.x, L.y / inertia.y, L.z / inertia.z});
}

}  // namespace trapdem
