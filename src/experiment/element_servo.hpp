#pragma once
// Stress-controlled walls for the element test: the two walls of a servo axis move in (or out)
// together at the speed that brings their mean normal stress to the target,
// proportional-integral:
//
//   u = K_p e + (K_p / T_i) sum_steps e,   e = sigma_target - sigma_wall  (u > 0: inwards),
//   K_p = alpha A / (N_c (k_n dt + c_n))   (N_c: the walls' mean number of contacts)
//
// K_p is the classic servo gain of PFC's wall servo (Itasca; also Cundall's membrane-free
// triaxial cells), with the contact's dashpot added: a wall moving at u for one step adds
// k_n u dt (the spring) and c_n u (the dashpot, c_n = 2 beta sqrt(m k_n) for the linear law,
// src/dem/contact/damping.hpp) to each of its N_c contacts, so a step then removes the fraction
// alpha of the force error. Without c_n the dashpot fed the wall's own speed back into its stress:
// c_n / (k_n dt) = 10 beta sqrt(m / m_min) at the usual time step 0.2 sqrt(m_min / k_n): 0.36 for
// restitution 0.9, but 2.5 for the tiny preset's 0.5 (beta = 0.22, 3.6-4.4 mm), where the loop
// gain alpha (1 + 2.5) exceeded 1 (each step's correction overshot) and the dense specimen's stresses sat
// 3-5 % above their target for 120 000 steps, so that it never counted as settled.
// N_c is averaged over the last ~100 steps: a gain that follows each step's count is largest
// when the stress is lowest (fewest contacts), and the integral would then balance sum K_p e,
// not sum e, leaving the mean stress off its target.
//
// The integral term carries the speed a wall needs while the specimen is sheared (a proportional
// servo alone lags by u / K_p, ~10 % of the stress here). Its price is exact: since the integral
// is the wall speed, over any interval the error's time integral is the change of the needed
// speed divided by K_i = K_p / (T_i dt). A row of element.csv (time T_row) therefore misses its
// target on average by Delta u T_i dt / (K_p T_row): largest over the first row of a dense
// specimen, whose lateral walls go from rest to the elastic and dilatant expansion. Measured on
// paper-calibrated, 1000 spheres, I = 2e-3 (biaxial): +0.93 % with T_i = 50 steps and the gain
// without c_n, +1.38 % with T_i = 50 and c_n (the smaller K_p), +0.29 % with T_i = 10 and c_n; the
// later rows within 0.27 %, 0.26 % and 0.04 %. At the contact level the loop with T_i = 10 stays
// well damped (the step map x' = x - alpha e - (alpha / T_i) sum e has the roots 0.88 and 0.57).
// The speed is capped (max_speed) so that the gas is compressed at a set rate, and the integral
// is clamped to the cap (no wind-up while the walls cross the gas).
#include <cstddef>
#include <vector>

#include "dem/simulation.hpp"
#include "experiment/element_box.hpp"

namespace trapdem {


// Number of particles touching each wall in the last step (index: the simulation's wall index).
std::vector<int> wall_contact_counts(const Simulation& sim);

// alpha tuned on 300-sphere specimens (docs/element.md): 0.02-0.1 let the row-mean lateral stress
// stray by 5-30 % when the shear starts and at stick-slip events; 0.3-0.5 held it. T_i: above.
struct ServoGains {
  double alpha = 0.5;            // fraction of the force error removed per step by the proportional term
  double integral_steps = 10;    // T_i in time steps
  double contact_average_steps = 100;  // N_c's exponential average, in time steps
};

// N s/m: what one particle-wall contact's force gains within a step per unit wall speed,
// k_n dt + c_n, for the box walls' law and the particles' mean mass (linear normal law).
double wall_contact_response(const Simulation& sim, const ElementBox& box);

class StressServo {
 public:
  StressServo() = default;
  // contact_response: wall_contact_response(sim, box).
  StressServo(double target_stress, double max_speed, double contact_response, ServoGains gains = ServoGains{})
      : target_(target_stress), max_speed_(max_speed), contact_response_(contact_response), gains_(gains) {}

  // Sets the velocity of both walls of `axis` from their current stresses (call once a step,
  // after step(), with `contacts` from wall_contact_counts).
  void update(Simulation& sim, const ElementBox& box, int axis, const std::vector<int>& contacts);
  void set_target(double target) { target_ = target; }
  void set_max_speed(double max_speed) { max_speed_ = max_speed; }
  double target() const { return target_; }

 private:
  double target_ = 0.0;      // Pa
  double max_speed_ = 0.0;   // m/s
  double contact_response_ = 0.0;  // N s/m
  ServoGains gains_;
  double integral_ = 0.0;    // m/s
  double mean_contacts_ = -1.0;  // N_c averaged (contact_average_steps); < 0 before the first update
};

}  // namespace trapdem
