#pragma once
// Contacts gathered in batches, so that the contact law runs over them as one loop the compiler
// vectorises (structure of arrays, contact-major): the pairs' (ContactBatch) and the walls'
// (WallBatch). Simulation::contacts() fills them, runs the law and adds the shares in contact order.
#include <cstdint>
#include <vector>

#include "dem/contact_kernel.hpp"
#include "dem/contact_law.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// The touching pairs of a stretch of a thread's block, gathered so that the contact law runs over
// them as one vectorisable loop (structure of arrays, contact-major): see Simulation::contacts().
struct ContactBatch {
  static constexpr std::uint32_t kCapacity = 64;
  alignas(64) std::uint32_t owner[kCapacity];
  alignas(64) std::uint32_t partner[kCapacity];
  alignas(64) std::uint32_t history_in[kCapacity];   // index of the pair's history of the last step
  alignas(64) std::uint32_t history_out[kCapacity];  // where this step's goes
  alignas(64) double separation[3][kCapacity];  // m, x_owner - x_partner (minimum image)
  alignas(64) double overlap_ratio[kCapacity];  // overlap / smaller radius
  alignas(64) double force[3][kCapacity];       // N, on the owner
  alignas(64) double torque_owner[3][kCapacity], torque_partner[3][kCapacity];  // N m
  alignas(64) double spring[3][kCapacity], rolling_spring[3][kCapacity];       // the new history
  alignas(64) std::uint32_t flags[kCapacity];
};

// Particle-wall contacts: the geometry (closest point, hidden seams) is found per particle before.
struct WallBatch {
  static constexpr std::uint32_t kCapacity = 64;
  std::uint32_t count = 0;
  // In: a particle's touching candidates follow each other, in candidate order.
  alignas(64) std::uint32_t particle[kCapacity];
  alignas(64) std::uint32_t candidate[kCapacity];  // index into the wall list (history, force)
  alignas(64) std::uint32_t wall[kCapacity];
  alignas(64) double normal[3][kCapacity];         // unit, from the wall's closest point to the centre
  alignas(64) double distance[kCapacity];          // m, centre to the closest point
  alignas(64) double point[3][kCapacity];          // m, closest point less the wall's origin
  alignas(64) double wall_velocity[3][kCapacity];  // m/s
  // Out: on the particle, and its new history.
  alignas(64) double force[3][kCapacity];          // N
  alignas(64) double torque[3][kCapacity];         // N m
  alignas(64) double spring[3][kCapacity], rolling_spring[3][kCapacity];
  alignas(64) std::uint32_t flags[kCapacity];
};

// The walls' contact constants, one entry per wall, as arrays the batch law reads per contact
// (a gather): walls of different friction share one batch. The law's choices (rolling model,
// lever arm, rolling stiffness, dashpot) are compiled in, so they must agree across the walls for
// the vectorised law: `uniform_choices` says whether they do.
struct WallLaws {
  std::vector<double> kn, kt, two_beta, mu_s, mu_k, mu_r, eta_r, sqrt_kt_over_kn;
  std::vector<ContactConstants> all;  // the same, whole (for the law with run-time choices)
  bool uniform_choices = true;

  void add(const ContactConstants& c) {
    if (!all.empty()) {
      const ContactConstants& a = all.front();
      uniform_choices = uniform_choices && a.rolling == c.rolling && a.effective_lever_arm == c.effective_lever_arm &&
                        a.rolling_stiffness_from_kt == c.rolling_stiffness_from_kt &&
                        a.needs_rolling_inertia == c.needs_rolling_inertia &&
                        a.needs_spin_inertia == c.needs_spin_inertia;
    }
    all.push_back(c);
    kn.push_back(c.kn);
    kt.push_back(c.kt);
    two_beta.push_back(c.two_beta);
    mu_s.push_back(c.mu_s);
    mu_k.push_back(c.mu_k);
    mu_r.push_back(c.mu_r);
    eta_r.push_back(c.eta_r);
    sqrt_kt_over_kn.push_back(c.sqrt_kt_over_kn);
  }
};

// A contact's force on its first body and its new history, into lane q of either batch.
template <class Batch>
[[gnu::always_inline]] inline void store_in_lane(Batch& batch, std::uint32_t q, const Vec3& force,
                                                 const ContactHistory& h) {
  batch.force[0][q] = force.x;
  batch.force[1][q] = force.y;
  batch.force[2][q] = force.z;
  batch.spring[0][q] = h.tangential_spring.x;
  batch.spring[1][q] = h.tangential_spring.y;
  batch.spring[2][q] = h.tangential_spring.z;
  batch.rolling_spring[0][q] = h.rolling_spring.x;
  batch.rolling_spring[1][q] = h.rolling_spring.y;
  batch.rolling_spring[2][q] = h.rolling_spring.z;
  batch.flags[q] = h.flags;
}

// The particle data the laws read.
struct BodyArrays {
  const double* __restrict radius;
  const double* __restrict mass;
  const double* __restrict inv_inertia;
  const Vec3* __restrict velocity;
  const Vec3* __restrict angular_velocity;
};

// Contact q of the batch under the constants c: the wall is a body of infinite mass and inertia
// that does not rotate, the rolling lever arm is the particle's radius.
[[gnu::always_inline]] inline void wall_contact_in_batch(WallBatch& batch, std::uint32_t q, const ContactConstants& c,
                                                         const BodyArrays& body, const ContactHistory* history,
                                                         double dt) {
  const std::uint32_t i = batch.particle[q];
  const Vec3 n{batch.normal[0][q], batch.normal[1][q], batch.normal[2][q]};
  const double ri = body.radius[i], mi = body.mass[i];
  const double dist = batch.distance[q];
  ContactBodies b;
  b.effective_mass = mi;
  b.arm_i = dist;
  b.arm_j = 0.0;
  b.lever = ri;
  const double inertia = 1.0 / body.inv_inertia[i];
  b.rolling_inertia = inertia + mi * ri * ri;
  b.spin_inertia = inertia;
  ContactHistory h = history[batch.candidate[q]];
  const Vec3 wall_velocity{batch.wall_velocity[0][q], batch.wall_velocity[1][q], batch.wall_velocity[2][q]};
  const ContactForce cf = contact_force(c, b, n, ri - dist, body.velocity[i] - wall_velocity,
                                        body.angular_velocity[i], Vec3{}, h, dt);
  const Vec3 torque = cf.rolling_torque - dist * cross(n, cf.tangential);
  store_in_lane(batch, q, cf.force, h);
  batch.torque[0][q] = torque.x;
  batch.torque[1][q] = torque.y;
  batch.torque[2][q] = torque.z;
}

// The law over the batch with the choices compiled in (all walls make the same choices): one
// loop the compiler vectorises; the constants are gathered per contact from the wall's entry.
struct WallBatchLaw {
  using Fn = void (*)(WallBatch&, const WallLaws&, const BodyArrays&, const ContactHistory*, double);
  template <int kRolling, bool kEffectiveLever, bool kRollingStiffnessFromKt, bool kRollingDashpot>
  static void run(WallBatch& batch, const WallLaws& laws, const BodyArrays& body, const ContactHistory* history,
                  double dt) {
    const double *kn = laws.kn.data(), *kt = laws.kt.data(), *two_beta = laws.two_beta.data();
    const double *mu_s = laws.mu_s.data(), *mu_k = laws.mu_k.data(), *mu_r = laws.mu_r.data();
    const double *eta_r = laws.eta_r.data(), *sqrt_kt_over_kn = laws.sqrt_kt_over_kn.data();
    const std::uint32_t count = batch.count;
    // The batch's output arrays never overlap what the loop reads.
#pragma GCC ivdep
    for (std::uint32_t q = 0; q < count; ++q) {
      const std::uint32_t k = batch.wall[q];
      ContactConstants c;
      c.kn = kn[k];
      c.kt = kt[k];
      c.two_beta = two_beta[k];
      c.mu_s = mu_s[k];
      c.mu_k = mu_k[k];
      c.mu_r = mu_r[k];
      c.eta_r = eta_r[k];
      c.sqrt_kt_over_kn = sqrt_kt_over_kn[k];
      c.rolling = kRolling;
      c.effective_lever_arm = kEffectiveLever;
      c.rolling_stiffness_from_kt = kRollingStiffnessFromKt;
      c.needs_rolling_inertia = kRollingDashpot;
      c.needs_spin_inertia = kRolling == 1;
      wall_contact_in_batch(batch, q, c, body, history, dt);
    }
  }
};

// The law over the batch with each wall's own choices, read at run time (walls that differ in
// rolling model or lever arm): the same law, contact by contact.
inline void wall_law_over_batch_any(WallBatch& batch, const WallLaws& laws, const BodyArrays& body,
                                    const ContactHistory* history, double dt) {
  for (std::uint32_t q = 0; q < batch.count; ++q) wall_contact_in_batch(batch, q, laws.all[batch.wall[q]], body, history, dt);
}

// The instance of a batch law (a struct with `Fn` and `run<kRolling, kEffectiveLever,
// kRollingStiffnessFromKt, kRollingDashpot>`) for the law's choices; the lever arm, stiffness and
// dashpot choices matter for the rolling models only.
template <class Kernel>
typename Kernel::Fn law_instance(const ContactConstants& c) {
  if (c.rolling == 0) return &Kernel::template run<0, false, false, false>;
  if (c.rolling == 1)
    return c.effective_lever_arm ? &Kernel::template run<1, true, false, false>
                                 : &Kernel::template run<1, false, false, false>;
  const bool damped = c.needs_rolling_inertia;
  if (c.effective_lever_arm) {
    if (c.rolling_stiffness_from_kt)
      return damped ? &Kernel::template run<2, true, true, true> : &Kernel::template run<2, true, true, false>;
    return damped ? &Kernel::template run<2, true, false, true> : &Kernel::template run<2, true, false, false>;
  }
  if (c.rolling_stiffness_from_kt)
    return damped ? &Kernel::template run<2, false, true, true> : &Kernel::template run<2, false, true, false>;
  return damped ? &Kernel::template run<2, false, false, true> : &Kernel::template run<2, false, false, false>;
}

}  // namespace trapdem
