#include "experiment/element_servo.hpp"

#include <algorithm>
#include <cstdlib>

#include "experiment/element_stress.hpp"

namespace trapdem {

std::vector<int> wall_contact_counts(const Simulation& sim) {
  std::vector<int> count(sim.walls().size(), 0);
  const WallList& wl = sim.wall_candidates();
  for (std::size_t k = 0; k < wl.wall.size(); ++k)
    if (!(wl.force[k] == Vec3{})) ++count[wl.wall[k]];
  return count;
}

void StressServo::update(Simulation& sim, const ElementBox& box, int axis, const std::vector<int>& contacts) {
  // The axis' two walls move in together at the same speed, from their mean stress: a servo per
  // wall would let an integral term carry both walls one way, the whole specimen sliding along
  // with them at no cost in stress.
  const double area = box.face_area(sim, axis);
  const double kn = sim.walls()[box.wall[axis][0]].law.normal_stiffness;
  const std::size_t lo = box.wall[axis][0], hi = box.wall[axis][1];
  const double error =
      target_ - 0.5 * (wall_normal_stress(sim, box, axis, 0) + wall_normal_stress(sim, box, axis, 1));
  const double wall_contacts = std::max(0.5 * (contacts[lo] + contacts[hi]), 1.0);
  const double kp = gains_.alpha * area / (kn * wall_contacts * sim.time_step());
  integral_ = std::clamp(integral_ + kp * error / gains_.integral_steps, -max_speed_, max_speed_);
  const double u = std::clamp(kp * error + integral_, -max_speed_, max_speed_);
  sim.set_wall_velocity(lo, u * sim.walls()[lo].normal);
  sim.set_wall_velocity(hi, u * sim.walls()[hi].normal);
}

}  // namespace trapdem
