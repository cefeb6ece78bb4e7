#pragma once
// What a normal model hands the other sub-models: the elastic force and the stiffnesses they
// scale with (the dashpots, the tangential spring, the EPSD rolling spring).

namespace trapdem {

struct NormalResponse {
  double elastic_force;         // N, repulsive
  double stiffness;             // N/m, secant k_n = F_elastic / delta (the EPSD rolling stiffness reads it)
  double damping_stiffness;     // N/m, S_n: the normal dashpot is c_n = factor sqrt(m* S_n) (damping.hpp)
  double tangential_stiffness;  // N/m, k_t of the tangential spring
  double sqrt_tangential_over_normal;  // sqrt(S_t / S_n): c_t = c_n sqrt(S_t / S_n), one square root less
};

}  // namespace trapdem
