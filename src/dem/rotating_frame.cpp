#include "dem/rotating_frame.hpp"

#include <cmath>

namespace trapdem {

FrameKick::FrameKick(const RotatingFrame& frame, double time, double half)
    : axis_point(frame.axis_point), axis(frame.axis) {
  const FrameSpin s = frame.spin ? frame.spin(time) : FrameSpin{};
  omega2 = s.omega * s.omega;
  alpha = frame.euler ? s.alpha : 0.0;
  if (frame.coriolis) {
    // dv/dt = -2 omega k x v turns v about k at the rate -2 omega.
    cos_turn = std::cos(-2.0 * s.omega * half);
    sin_turn = std::sin(-2.0 * s.omega * half);
  }
}

void frame_first_half_kick(Particles& p, std::size_t n, const FrameKick& frame, double half) {
  const Vec3* x = p.position.data();
  Vec3* v = p.velocity.data();
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) v[i] = frame.coriolis_turn(v[i]) + half * frame.acceleration(x[i]);
}

double frame_potential_energy(const Particles& p, std::size_t n, const RotatingFrame& frame, double time,
                              double reference_radius) {
  const FrameSpin s = frame.spin ? frame.spin(time) : FrameSpin{};
  const double w2 = s.omega * s.omega;
  double e = 0.0;
  for (std::size_t i = 0; i < n; ++i)
    e += 0.5 * p.mass[i] * w2 * (reference_radius * reference_radius - norm2(frame.radius_vector(p.position[i])));
  return e;
}

}  // namespace trapdem
