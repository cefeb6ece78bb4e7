#pragma once
// Stress-controlled walls for the element test: the two walls of a servo axis move in (or out)
// together at the speed that brings their mean normal stress to the target,
// proportional-integral:
//
//   u = K_p e + (K_p / T_i) sum_steps e,   e = sigma_target - sigma_wall  (u > 0: inwards),
//   K_p = alpha A / (k_n N_c dt)   (N_c: the walls' mean number of contacts)
//
// K_p is the classic servo gain of PFC's wall servo (Itasca; also Cundall's membrane-free
// triaxial cells): a step's wall displacement u dt then removes the fraction alpha of the force
// error if the wall's N_c contacts were springs k_n in parallel. The integral term carries the
// steady speed a wall needs while the specimen is sheared (a proportional servo alone lags a
// ramp by u / K_p, several per cent of the stress here), so the mean stress sits on its target.
// The speed is capped (max_speed) so that the gas is compressed at a set rate, and the integral
// is clamped to the cap (no wind-up while the walls cross the gas).
#include <cstddef>
#include <vector>

#include "dem/simulation.hpp"
#include "experiment/element_box.hpp"

namespace trapdem {


// Number of particles touching each wall in the last step (index: the simulation's wall index).
std::vector<int> wall_contact_counts(const Simulation& sim);

// Tuned on 300-sphere specimens (docs/element.md): alpha 0.02-0.1 let the row-mean lateral stress
// stray by 5-30 % when the shear starts and at stick-slip events; 0.3-0.5 with T_i of 20-50 steps
// hold it within 0.3 % without changing the angles beyond their scatter.
struct ServoGains {
  double alpha = 0.5;            // fraction of the force error removed per step by the proportional term
  double integral_steps = 50;    // T_i in time steps
};

class StressServo {
 public:
  StressServo() = default;
  StressServo(double target_stress, double max_speed, ServoGains gains = ServoGains{})
      : target_(target_stress), max_speed_(max_speed), gains_(gains) {}

  // Sets the velocity of both walls of `axis` from their current stresses (call once a step,
  // after step(), with `contacts` from wall_contact_counts).
  void update(Simulation& sim, const ElementBox& box, int axis, const std::vector<int>& contacts);
  void set_target(double target) { target_ = target; }
  void set_max_speed(double max_speed) { max_speed_ = max_speed; }
  double target() const { return target_; }

 private:
  double target_ = 0.0;      // Pa
  double max_speed_ = 0.0;   // m/s
  ServoGains gains_;
  double integral_ = 0.0;    // m/s
};

}  // namespace trapdem
