#pragma once
// The incremental tangential spring that the spring-based tangential models share (seed eq. 2's
// integral): the stored displacement turned into the current tangent plane, then advanced by the
// slip of this step.
#include <cmath>

#include "dem/vec3.hpp"

namespace trapdem {

// The spring s (m) turned into the tangent plane of normal n with its length kept (the contact
// has rotated since the last step), plus v_t dt. The contact turns by a tiny angle per step in a
// dense, slow packing; when the spring's out-of-plane part x = (s.n)^2 / |s|^2 is below 1e-12 the
// rescaling 1 / sqrt(1 - x) differs from 1 by less than 5e-13, and the square root and division
// (a sixth of the pair loop's time) are skipped. The vectors are taken by value: a reference to
// the caller's history keeps GCC from vectorising the batch loops (dem.batch_loops_vectorise).
[[gnu::always_inline]] inline Vec3 advanced_spring(Vec3 spring, Vec3 n, Vec3 vt, double dt) {
  Vec3 s = spring;
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
  return s;
}

}  // namespace trapdem
