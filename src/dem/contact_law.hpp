#pragma once
// The contact law's parameters as the user gives them (the seed paper's eqs. 1-5, and Hertz-
// Mindlin), their validation, and the critical time step they set. The engine turns them into
// the sub-models' parameters (law_params, contact/law.hpp) and choices (law_choices).
#include <string>
#include <vector>

#include "dem/contact/choices.hpp"
#include "dem/contact/law_parameter.hpp"

namespace trapdem {

struct ContactLaw {
  NormalModel normal_model = NormalModel::linear;
  double normal_stiffness = 1.0e6;        // k_n, N/m (linear)
  double tangential_stiffness = 0.5e6;    // k_t, N/m (linear; the paper: k_n / 2)
  double youngs_modulus = 0.0;            // E, Pa (hertz): of the particles' material, or of a wall's
  double poisson_ratio = 0.3;             // nu (hertz), in [0, 0.5)
  double restitution = 0.9;               // e in (0, 1]; sets both dashpots
  DampingModel damping_model = DampingModel::restitution;
  TangentialModel tangential_model = TangentialModel::coulomb;
  double static_friction = 0.5;           // mu_s: the stick limit |F_t| <= mu_s |F_n|
  double kinetic_friction = 0.5;          // mu_k: |F_t| = mu_k |F_n| while sliding (the Blaze models: their strength)
  double rolling_friction = 0.0;          // mu_r (dimensionless): M_max = mu_r R |F_n|; angular_damping: 1 - mu_r per reference step
  RollingModel rolling_model = RollingModel::none;
  RollingLeverArm lever_arm = RollingLeverArm::average_radius;
  RollingStiffness rolling_stiffness = RollingStiffness::ai2011;
  double rolling_damping = 0.3;           // eta_r of the EPSD dashpot (Ai et al. 2011 use 0.3)
  // Blaze-DEM's law (tangential_blaze_viscous.hpp, tangential_blaze_tresca.hpp, rolling_angular_damping.hpp): its time step
  // sets the tangential force's scale and the angular damping's rate.
  double reference_time_step = 0.0;       // s, dt_ref (0: unset; required by those models)
  double blaze_velocity_scale = 5.0e-4;   // m/s, u0 (Blaze's literal 0.05 cm/s)
  double blaze_rest_speed = 0.01;         // m/s, V when the centres' relative speed is 0 (Blaze's 1 cm/s)

  // The restitution the dashpots are set from: e, or Blaze-DEM's e - 0.03808 for 0.3 <= e <= 0.9.
  double damping_restitution() const;

  // beta = -ln e / sqrt(ln^2 e + pi^2) of damping_restitution(); the dashpot is c = f beta sqrt(m* S_n)
  // (contact/damping.hpp).
  double damping_ratio() const;
  // Throws InputError naming the parameter (prefixed by `where`) when a value is impossible.
  void validate(const std::string& where) const;
  // The material's Young's modulus and Poisson's ratio (a Hertz contact reads both bodies').
  void validate_material(const std::string& where) const;
};

// The parameters the law's chosen models read (contact/law_parameter.hpp), in the order normal,
// damping, tangential, rolling; the rolling model's only when mu_r != 0 (a rolling model with
// mu_r = 0 is off). What validate checks and the configuration reader requires.
std::vector<LawParameter> active_parameters(const ContactLaw& law);
// The parameters of the models the law names, its rolling model's whatever mu_r (with the bounds
// that model gives them: rolling_friction below 1 under angular_damping).
std::vector<LawParameter> chosen_parameters(const ContactLaw& law);
// Every model's parameters, each key once, in the model lists' order with rolling_friction first
// (whether a rolling model is on depends on it): what the configuration reader reads.
std::vector<LawParameter> declared_parameters();
// The choices under which a key is read, for messages: normal_model = "linear"; tangential_model =
// "blaze_viscous" or "blaze_tresca", or rolling_model = "angular_damping" with rolling_friction > 0.
std::string readers_of(std::string_view key);

// The law's choices as the compiler sees them (rolling none when mu_r = 0: every rolling model
// scales with mu_r, angular_damping's factor 1 - mu_r included; canonical).
LawChoices law_choices(const ContactLaw& law);

// The factor on every particle's angular velocity per engine step of dt (s): 1 unless the law's
// rolling model damps spin (rolling_angular_damping.hpp).
double spin_retention(const ContactLaw& law, double dt);

// The value named `name` of a choice (e.g. parse_choice<RollingModel>("elastic_plastic")).
template <class E>
E parse_choice(std::string_view name);

// s, the time scale of contacts under `law` of a particle of mass m (kg) and radius r (m) made
// of the particle law's material (the normal model's: sqrt(m / k_n) for the linear spring, the
// Rayleigh time for Hertz). The time step is a fraction of it.
double contact_time_scale(const ContactLaw& law, const ContactLaw& particle_law, double mass, double radius);
// s, the smallest time scale over the particle law and the walls' laws for that particle: what
// both the engine (Simulation::critical_time_step) and the configuration check call.
double critical_time_step(const ContactLaw& particle_law, const std::vector<const ContactLaw*>& wall_laws, double mass,
                          double radius);

// Whether the law's normal model combines both bodies' materials (Hertz: a wall's contact reads the
// particles' E and nu too, so they must be valid).
bool combines_materials(const ContactLaw& law);
// The parameter that sets the law's contact stiffness (k_n for the linear spring, E for Hertz).
const LawParameter& stiffness_parameter(const ContactLaw& law);

// How critical_time_step is computed for these laws, for messages: "sqrt(m_min/k_max)" for
// linear springs, "the Rayleigh time T_R" for Hertz, both for a mix.
std::string critical_time_step_formula(const ContactLaw& particle_law, const std::vector<const ContactLaw*>& wall_laws);
// The law in one line for logs: its models and the parameters they read with their values and
// units ("linear normal, restitution damping, coulomb tangential, none rolling: normal_stiffness =
// 5e+04 N/m, ...").
std::string describe_law(const ContactLaw& law);
// The law's stiffness parameter and its value, for messages: "normal stiffness of the <owner>
// contact law (1e+06 N/m)" (linear), "Young's modulus of the <owner> contact law (5e+07 Pa)" (Hertz).
std::string describe_stiffness(const ContactLaw& law, const std::string& owner);

}  // namespace trapdem
