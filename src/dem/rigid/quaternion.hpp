#pragma once
// Unit quaternions for the orientation of a rigid body (a clump): q = (w, x, y, z) takes body-frame
// vectors to the space frame, v_space = q v_body q*. Hamilton's convention, as LAMMPS's math_extra
// and Eigen use.
#include <cmath>

#include "dem/vec3.hpp"

namespace trapdem {

struct Quaternion {
  double w = 1.0, x = 0.0, y = 0.0, z = 0.0;

  static Quaternion about_axis(const Vec3& unit_axis, double angle_rad) {
    const double s = std::sin(0.5 * angle_rad);
    return {std::cos(0.5 * angle_rad), s * unit_axis.x, s * unit_axis.y, s * unit_axis.z};
  }
};

// A rotation drawn uniformly over all orientations from three numbers uniform in [0, 1)
// (Shoemake 1992, "Uniform random rotations", Graphics Gems III, p. 124).
inline Quaternion uniform_orientation(double u1, double u2, double u3) {
  constexpr double kTwoPi = 6.283185307179586;
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return {b * std::cos(kTwoPi * u3), a * std::sin(kTwoPi * u2), a * std::cos(kTwoPi * u2), b * std::sin(kTwoPi * u3)};
}

constexpr Quaternion operator*(const Quaternion& a, const Quaternion& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

constexpr Quaternion conjugate(const Quaternion& q) { return {q.w, -q.x, -q.y, -q.z}; }

inline Quaternion normalised(const Quaternion& q) {
  const double n = std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w / n, q.x / n, q.y / n, q.z / n};
}

// q v q*: a body-frame vector in the space frame.
constexpr Vec3 rotate(const Quaternion& q, const Vec3& v) {
  // v + 2 w (u x v) + 2 u x (u x v), u the vector part (the expansion of q v q* for a unit q).
  const Vec3 u{q.x, q.y, q.z};
  const Vec3 t = 2.0 * cross(u, v);
  return v + q.w * t + cross(u, t);
}

// q* v q: a space-frame vector in the body frame.
constexpr Vec3 rotate_inverse(const Quaternion& q, const Vec3& v) { return rotate(conjugate(q), v); }

}  // namespace trapdem
