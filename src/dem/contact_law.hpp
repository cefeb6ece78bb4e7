#pragma once
// Parameters of the linear spring-dashpot contact law with Coulomb friction and rolling
// resistance (the seed paper's eqs. 1-5), and the derived constants the kernel uses.
#include <string>

namespace trapdem {

enum class RollingModel {
  none,
  constant_torque,   // Ai et al. (2011) type A: M = mu_r R |F_n| opposing the relative rolling (seed eq. 5)
  elastic_plastic,   // Ai et al. (2011) type C (EPSD): spring torque capped at mu_r R |F_n|, dashpot below it
};

enum class RollingLeverArm {
  average_radius,    // R = (r_i + r_j) / 2, the seed paper's "average particle radius"
  effective_radius,  // R = r_i r_j / (r_i + r_j), Ai et al. (2011) and LIGGGHTS; half as large for equal spheres
};

enum class RollingStiffness {
  ai2011,            // k_r = 2.25 k_n mu_r^2 R^2 (Ai et al. 2011, eq. 15)
  tangential,        // k_r = k_t R^2 (LIGGGHTS epsd2, LAMMPS "rolling sds k_t")
};

struct ContactLaw {
  double normal_stiffness = 1.0e6;        // k_n, N/m
  double tangential_stiffness = 0.5e6;    // k_t, N/m (the paper: k_n / 2)
  double restitution = 0.9;               // e in (0, 1]; sets both dashpots
  double static_friction = 0.5;           // mu_s: the stick limit |F_t| <= mu_s |F_n|
  double kinetic_friction = 0.5;          // mu_k: |F_t| = mu_k |F_n| while sliding
  double rolling_friction = 0.0;          // mu_r (dimensionless): M_max = mu_r R |F_n|
  RollingModel rolling_model = RollingModel::none;
  RollingLeverArm lever_arm = RollingLeverArm::average_radius;
  RollingStiffness rolling_stiffness = RollingStiffness::ai2011;
  double rolling_damping = 0.3;           // eta_r of the EPSD dashpot (Ai et al. 2011 use 0.3)

  // beta = -ln e / sqrt(ln^2 e + pi^2); the dashpot is c = 2 beta sqrt(m* k).
  double damping_ratio() const;
  // Throws InputError naming the parameter (prefixed by `where`) when a value is impossible.
  void validate(const std::string& where) const;
};

RollingModel parse_rolling_model(const std::string& name);
RollingLeverArm parse_lever_arm(const std::string& name);
RollingStiffness parse_rolling_stiffness(const std::string& name);
const char* to_string(RollingModel model);
const char* to_string(RollingLeverArm arm);
const char* to_string(RollingStiffness stiffness);

// The law's constants in the form the kernel reads them (no logs or branches on enums per contact).
struct ContactConstants {
  double kn = 0.0, kt = 0.0;
  double two_beta = 0.0;                  // 2 beta
  double mu_s = 0.0, mu_k = 0.0, mu_r = 0.0;
  int rolling = 0;                        // 0 none, 1 constant torque, 2 elastic-plastic
  bool effective_lever_arm = false;
  bool rolling_stiffness_from_kt = false;
  double eta_r = 0.0;
  double sqrt_kt_over_kn = 0.0;           // c_t = c_n sqrt(k_t / k_n): one square root per contact less
  bool needs_rolling_inertia = false;     // EPSD with a dashpot (eta_r > 0)
  bool needs_spin_inertia = false;        // constant torque (its anti-chatter bound)
};
ContactConstants make_constants(const ContactLaw& law);

}  // namespace trapdem
