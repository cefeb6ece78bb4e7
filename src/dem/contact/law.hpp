#pragma once
// The contact law composed of its sub-models (models.hpp lists them): normal (normal_linear.hpp,
// normal_hertz.hpp), damping (damping.hpp), tangential (tangential_coulomb.hpp: spring with
// static/kinetic friction; tangential_blaze_viscous.hpp, tangential_blaze_tresca.hpp) and rolling
// (rolling_none.hpp, rolling_constant_torque.hpp, rolling_epsd.hpp, rolling_angular_damping.hpp).
// ContactEvaluator<choices> holds the whole law for one set of choices; the pair and wall batch
// loops (pair_sweep.cpp, wall_sweep.cpp) call it, each written once for every law
// (law_dispatch.hpp picks the instance). Its branches on per-contact values must stay
// if-convertible (selects, no loads or stores of memory under them) for those loops to vectorise.
#include <cmath>
#include <cstddef>

#include "dem/contact/bodies.hpp"
#include "dem/contact/choices.hpp"
#include "dem/contact/contact_history.hpp"
#include "dem/contact/damping.hpp"
#include "dem/contact/models.hpp"
#include "dem/contact/sub_model_inputs.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// The parameters of every sub-model of one law (each axis's model of the law's choice only; the
// others' are left at their defaults).
struct LawParams {
  NormalModels::Params normal;
  RestitutionDamping::Params damping;
  TangentialModels::Params tangential;
  double mu_r = 0.0;  // rolling friction: M_max = mu_r R |F_n| (seed eq. 5); Blaze's angular damping
  RollingModels::Params rolling;
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
  using Tangential = TangentialModels::Model<kLaw.tangential>;
  using Rolling = RollingModels::Model<kLaw.rolling>;

  // normal: unit vector from body j towards body i; overlap > 0 (m); relative_velocity: v_i - v_j
  // of the centres (m/s); w_i, w_j angular velocities (rad/s). Marks the history touching (and
  // sliding as the tangential model says): every law keeps its contacts across list rebuilds.
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

    TangentialInputs tangential_in;
    tangential_in.normal = n;
    tangential_in.slip_velocity = vt;
    tangential_in.normal_force = fn_abs;
    tangential_in.stiffness = r.tangential_stiffness;
    tangential_in.dashpot = c_n * r.sqrt_tangential_over_normal;
    tangential_in.centre_speed = Tangential::needs_tangential_mass ? norm(relative_velocity) : 0.0;  // Blaze-DEM's models
    tangential_in.mean_mass = b.mean_mass;
    tangential_in.tangential_mass = b.tangential_mass;
    tangential_in.dt = dt;
    const TangentialResponse t =
        Tangential::force(static_cast<const typename Tangential::Params&>(p.tangential), h, tangential_in);
    h.flags = ContactHistory::kTouching | (t.sliding ? ContactHistory::kSliding : 0u);

    Vec3 rolling_torque{};
    if constexpr (Rolling::has_torque) {
      // Relative rolling: the relative angular velocity less its twist about the normal.
      Vec3 wr = w_i - w_j;
      wr -= dot(wr, n) * n;
      const RollingInputs rolling_in{n,
                                     wr,
                                     p.mu_r * b.lever * fn_abs,  // seed eq. 5
                                     p.mu_r,
                                     b.lever,
                                     r.stiffness,
                                     r.tangential_stiffness,
                                     b.rolling_inertia,
                                     b.spin_inertia,
                                     dt};
      rolling_torque =
          Rolling::template torque<kLaw>(static_cast<const typename Rolling::Params&>(p.rolling), h, rolling_in);
    }
    // The tangential part copied member by member: an aggregate copy of t.force keeps GCC from
    // turning the batch loops' structs into scalars, and the loops then do not vectorise.
    return {fn * n + t.force, Vec3{t.force.x, t.force.y, t.force.z}, rolling_torque, fn};
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
