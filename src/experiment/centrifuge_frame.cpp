#include "experiment/centrifuge_frame.hpp"

#include <cmath>

namespace trapdem {

double centrifuge_angular_velocity(double g_level, double radius) {
  return std::sqrt(g_level * ExperimentConfig::standard_gravity / radius);
}

double centrifuge_radius_at(const CentrifugeConfig& c, double z) { return c.radius + c.reference_height() - z; }

namespace {

// omega from w1 to wn (rad/s) linearly over `ramp` (s) from `start`, constant before and after.
FrameSpin linear_ramp(double w1, double wn, double ramp, double start, double t) {
  if (!(ramp > 0.0)) return {wn, 0.0};
  const double f = (t - start) / ramp;
  if (f < 0.0) return {w1, 0.0};
  if (f >= 1.0) return {wn, 0.0};
  return {w1 + (wn - w1) * f, (wn - w1) / ramp};
}

}  // namespace

FrameSpin centrifuge_spin(const ExperimentConfig& e, double ramp_start, double t) {
  return linear_ramp(centrifuge_angular_velocity(1.0, e.centrifuge.radius),
                     centrifuge_angular_velocity(e.spin_up.g_level, e.centrifuge.radius), e.spin_up.ramp_time,
                     ramp_start, t);
}

RotatingFrame centrifuge_frame(const ExperimentConfig& e, double ramp_start, bool ramped) {
  const CentrifugeConfig& c = e.centrifuge;
  RotatingFrame f;
  f.axis_point = {0.5 * e.box.width, 0.5 * e.box.depth, c.reference_height() + c.radius};
  f.axis = c.width_in_plane ? Vec3{0.0, -1.0, 0.0} : Vec3{1.0, 0.0, 0.0};
  f.coriolis = c.coriolis;
  f.euler = c.euler;
  const double w1 = centrifuge_angular_velocity(1.0, c.radius), wn = centrifuge_angular_velocity(e.spin_up.g_level, c.radius);
  const double ramp = ramped ? e.spin_up.ramp_time : 0.0;
  f.spin = [=](double t) { return linear_ramp(w1, wn, ramp, ramp_start, t); };
  return f;
}

}  // namespace trapdem
