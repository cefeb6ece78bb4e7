#pragma once
// The contact law composed of its sub-models: normal (normal_linear.hpp, normal_hertz.hpp),
// damping (damping.hpp), tangential with static/kinetic friction (tangential_coulomb.hpp) and
// rolling (none, rolling_constant_torque.hpp, rolling_epsd.hpp). ContactEvaluator<choices> holds
// the whole law for one set of choices; the pair and wall batch loops (pair_sweep.cpp,
// wall_sweep.cpp) call it, each written once for every law (law_dispatch.hpp picks the instance).
// Its branches on per-contact values must stay if-convertible (selects, no loads or stores of
// memory under them) for those loops to vectorise.
#include <cstddef>
#include <tuple>

#include "dem/contact/bodies.hpp"
#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/damping.hpp"
#include "dem/contact/normal_hertz.hpp"
#include "dem/contact/normal_linear.hpp"
#include "dem/contact/rolling_constant_torque.hpp"
#include "dem/contact/rolling_epsd.hpp"
#include "dem/contact/tangential_coulomb.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// The normal models, each a struct with `model` (its NormalModel value), `damping_scale`,
// `Params`, `params(law, particle_law)`, `respond(params, overlap, R*)` and
// `time_scale(law, particle_law, mass, radius)`. A new model is added to this list.
template <class... Models>
struct NormalModelList {
  // Each model's parameters, one base each (a trivially copyable block of doubles, unlike a
  // std::tuple: WallLaws copies it as such): static_cast<const Model::Params&>(params).
  struct Params : Models::Params... {};
  static constexpr std::size_t index_of(NormalModel m) {
    constexpr NormalModel listed[] = {Models::model...};
    for (std::size_t k = 0; k < sizeof...(Models); ++k)
      if (listed[k] == m) return k;
    return sizeof...(Models);
  }
  template <NormalModel m>
  using Model = std::tuple_element_t<index_of(m), std::tuple<Models...>>;
  // f(Model{}) for the model of value m (a run-time choice: parameters, time step).
  template <class F>
  static auto visit(NormalModel m, F&& f) {
    using R = decltype(f(std::tuple_element_t<0, std::tuple<Models...>>{}));
    R result{};
    ((m == Models::model ? (void)(result = f(Models{})) : (void)0), ...);
    return result;
  }
};
using NormalModels = NormalModelList<NormalLinear, NormalHertz>;

// The parameters of every sub-model of one law (the normal model's of the law's choice only).
struct LawParams {
  NormalModels::Params normal;
  RestitutionDamping::Params damping;
  CoulombTangential::Params tangential;
  double mu_r = 0.0;   // rolling friction: M_max = mu_r R |F_n| (seed eq. 5)
  double eta_r = 0.0;  // EPSD dashpot's damping ratio
};

// The law's parameters from the user's: `law` is the particle law or a wall's; a Hertz wall
// contact reads the particles' material from `particle_law` (contact_law.cpp).
LawParams law_params(const ContactLaw& law, const ContactLaw& particle_law);

struct ContactForce {
  Vec3 force;                // N, on body i (body j receives -force)
  Vec3 tangential;           // N, the tangential part of force (for the torques r x F_t)
  Vec3 rolling_torque;       // N m, on body i (body j receives -rolling_torque)
  double normal_force;       // N, signed: positive when repulsive
};

template <LawChoices kLaw>
struct ContactEvaluator {
  static_assert(kLaw == kLaw.canonical(), "one instance per distinct law: use canonical choices");
  using Normal = NormalModels::Model<kLaw.normal>;

  // normal: unit vector from body j towards body i; overlap > 0 (m); relative_velocity: v_i - v_j
  // of the centres (m/s); w_i, w_j angular velocities (rad/s).
  [[gnu::always_inline]] static ContactForce evaluate(const LawParams& p, const ContactBodies& b, const Vec3& n,
                                                      double overlap, const Vec3& relative_velocity, const Vec3& w_i,
                                                      const Vec3& w_j, ContactHistory& h, double dt) {
    // Relative velocity of the contact points: v_i + w_i x (-a_i n) - (v_j + w_j x (a_j n)).
    const Vec3 v = relative_velocity - cross(b.arm_i * w_i + b.arm_j * w_j, n);
    const double vn = dot(v, n);
    const Vec3 vt = v - vn * n;

    // F_n = elastic - c_n v_n. Not clamped at zero: the dashpot may pull briefly as a collision
    // ends, which is what makes e come out as set.
    const NormalResponse r = Normal::respond(static_cast<const typename Normal::Params&>(p.normal), overlap, b.effective_radius);
    const double c_n = RestitutionDamping::normal_coefficient(p.damping, b.effective_mass, r.damping_stiffness);
    const double fn = r.elastic_force - c_n * vn;
    const double fn_abs = std::fabs(fn);

    const double c_t = c_n * r.sqrt_tangential_over_normal;
    const Vec3 ft = CoulombTangential::force(p.tangential, h, n, vt, r.tangential_stiffness, c_t, fn_abs, dt);

    Vec3 rolling_torque{};
    if constexpr (kLaw.rolling != RollingModel::none) {
      // Relative rolling: the relative angular velocity less its twist about the normal.
      Vec3 wr = w_i - w_j;
      wr -= dot(wr, n) * n;
      const double m_max = p.mu_r * b.lever * fn_abs;  // seed eq. 5
      if constexpr (kLaw.rolling == RollingModel::constant_torque)
        rolling_torque = ConstantTorqueRolling::torque(wr, m_max, b.spin_inertia, dt);
      else
        rolling_torque = EpsdRolling::torque<kLaw.rolling_stiffness, kLaw.rolling_dashpot>(
            h, n, wr, p.mu_r, m_max, b.lever, r.stiffness, r.tangential_stiffness, p.eta_r, b.rolling_inertia, dt);
    }
    return {fn * n + ft, Vec3{ft.x, ft.y, ft.z}, rolling_torque, fn};
  }
};

// The torque assembly: r x F_t of each body's lever arm plus the rolling torque (body j's
// unused for a wall).
struct ContactTorques {
  Vec3 on_i, on_j;  // N m
};
[[gnu::always_inline]] inline ContactTorques contact_torques(const ContactForce& f, const ContactBodies& b,
                                                             const Vec3& n) {
  const Vec3 n_x_ft = cross(n, f.tangential);
  return {f.rolling_torque - b.arm_i * n_x_ft, -f.rolling_torque - b.arm_j * n_x_ft};
}

}  // namespace trapdem
