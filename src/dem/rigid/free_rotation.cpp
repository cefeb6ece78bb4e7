#include "dem/rigid/free_rotation.hpp"

namespace trapdem {

namespace {

// R_k(h): the body turns by theta = h L_k / I_k about its own axis k; seen from the body, the
// (fixed) space-frame angular momentum turns by -theta about that axis.
void rotate_about_body_axis(int k, Quaternion& q, Vec3& L, const Vec3& inertia, double h) {
  if (!(inertia[k] > 0.0)) return;
  const double theta = h * L[k] / inertia[k];
  Vec3 axis{};
  axis[k] = 1.0;
  q = q * Quaternion::about_axis(axis, theta);
  const double c = std::cos(theta), s = std::sin(theta);
  const int a = (k + 1) % 3, b = (k + 2) % 3;  // L_body <- R_k(-theta) L_body
  const double La = L[a], Lb = L[b];
  L[a] = c * La + s * Lb;
  L[b] = -s * La + c * Lb;
}

}  // namespace

void rotate_freely(Quaternion& q, Vec3& momentum_body, const Vec3& inertia, double dt) {
  // Miller et al. (2002): the symmetric splitting, the third axis outermost.
  rotate_about_body_axis(2, q, momentum_body, inertia, 0.5 * dt);
  rotate_about_body_axis(1, q, momentum_body, inertia, 0.5 * dt);
  rotate_about_body_axis(0, q, momentum_body, inertia, dt);
  rotate_about_body_axis(1, q, momentum_body, inertia, 0.5 * dt);
  rotate_about_body_axis(2, q, momentum_body, inertia, 0.5 * dt);
  q = normalised(q);
}

Vec3 angular_velocity_space(const Quaternion& q, const Vec3& L, const Vec3& inertia) {
  return rotate(q, Vec3{L.x / inertia.x, L.y / inertia.y, L.z / inertia.z});
}

}  // namespace trapdem
