#include "experiment/element_servo.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "dem/contact/law.hpp"
#include "experiment/element_stress.hpp"

namespace trapdem {

std::vector<int> wall_contact_counts(const Simulation& sim) {
  std::vector<int> count(sim.walls().size(), 0);
  const WallList& wl = sim.wall_candidates();
  for (std::size_t k = 0; k < wl.wall.size(); ++k)
    if (!(wl.force[k] == Vec3{})) ++count[wl.wall[k]];
  return count;
}

double wall_contact_response(const Simulation& sim, const ElementBox& box) {
  const Wall& wall = sim.walls()[box.wall[0][0]];
  const Particles& p = sim.particles();
  const double mass = p.empty() ? 0.0 : p.total_mass() / double(p.size());
  const double kn = wall.law.normal_stiffness;
  // A wall is a body of infinite mass: the contact's effective mass is the particle's.
  const double cn = law_params(wall.law, sim.particle_law()).damping.factor * std::sqrt(mass * kn);
  return kn * sim.time_step() + cn;
}

void StressServo::update(Simulation& sim, const ElementBox& box, int axis, const std::vector<int>& contacts) {
  // The axis' two walls move in together at the same speed, from their mean stress: a servo per
  // wall would let an integral term carry both walls one way, the whole specimen sliding along
  // with them at no cost in stress.
  const double area = box.face_area(sim, axis);
  const std::size_t lo = box.wall[axis][0], hi = box.wall[axis][1];
  const double error =
      target_ - 0.5 * (wall_normal_stress(sim, box, axis, 0) + wall_normal_stress(sim, box, axis, 1));
  const double wall_contacts = 0.5 * (contacts[lo] + contacts[hi]);
  mean_contacts_ = mean_contacts_ < 0.0 ? wall_contacts
                                        : mean_contacts_ + (wall_contacts - mean_contacts_) / gains_.contact_average_steps;
  const double kp = gains_.alpha * area / (std::max(mean_contacts_, 1.0) * contact_response_);
  integral_ = std::clamp(integral_ + kp * error / gains_.integral_steps, -max_speed_, max_speed_);
  const double u = std::clamp(kp * error + integral_, -max_speed_, max_speed_);
  sim.set_wall_velocity(lo, u * sim.walls()[lo].normal);
  sim.set_wall_velocity(hi, u * sim.walls()[hi].normal);
}

}  // namespace trapdem
