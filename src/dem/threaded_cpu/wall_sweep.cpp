#include "dem/threaded_cpu/wall_sweep.hpp"

#include <algorithm>

#include "dem/threaded_cpu/batch_lane.hpp"
#include "dem/contact/law_dispatch.hpp"

namespace trapdem {

namespace {

// The law over lanes [from, to) of the batch, compiled for one set of choices: one loop the
// compiler vectorises; the parameters are gathered per contact from the contact's wall entry.
// A wall is a body of infinite mass and inertia that does not rotate (contact/bodies.hpp).
struct WallBatchLaw {
  using Fn = void (*)(WallBatch&, std::uint32_t, std::uint32_t, const WallLaws::View&, const BodyArrays&,
                      const ContactHistory*, double);
  template <LawChoices kLaw>
  static void run(WallBatch& batch, std::uint32_t from, std::uint32_t to, const WallLaws::View& laws,
                  const BodyArrays& body, const ContactHistory* history, double dt) {
    // The batch's output arrays never overlap what the loop reads.
#pragma GCC ivdep
    for (std::uint32_t q = from; q < to; ++q) {
      const LawParams law = laws.of(batch.wall[q]);
      const std::uint32_t i = batch.particle[q];
      const Vec3 n{batch.normal[0][q], batch.normal[1][q], batch.normal[2][q]};
      const double ri = body.radius[i];
      const double dist = batch.distance[q];
      const double overlap = ri - dist;
      const ContactBodies b = reduce_bodies<kLaw, SecondBody::wall>(
          Body{body.mass[i], ri, body.inv_inertia[i]}, Body{0.0, 0.0, 0.0}, overlap, dist);
      ContactHistory h = history[batch.candidate[q]];
      const Vec3 wall_velocity{batch.wall_velocity[0][q], batch.wall_velocity[1][q], batch.wall_velocity[2][q]};
      const ContactForce cf = ContactEvaluator<kLaw>::evaluate(law, b, n, overlap, body.velocity[i] - wall_velocity,
                                                               body.angular_velocity[i], Vec3{}, h, dt);
      const Vec3 torque = contact_torques(cf, b, n).on_i;
      store_in_lane(batch, q, cf.force, h);
      batch.torque[0][q] = torque.x;
      batch.torque[1][q] = torque.y;
      batch.torque[2][q] = torque.z;
    }
  }
};

// The law over the whole batch: one loop when the walls' choices agree, else one per stretch of
// contacts whose walls make the same choices.
void wall_law_over_batch(WallBatch& batch, const WallLaws& laws, const BodyArrays& body, const ContactHistory* history,
                         double dt) {
  if (batch.count == 0) return;
  const WallLaws::View columns = laws.view();
  if (laws.uniform) {
    law_instance<WallBatchLaw>(laws.choices.front())(batch, 0, batch.count, columns, body, history, dt);
    return;
  }
  for (std::uint32_t from = 0; from < batch.count;) {
    const LawChoices& choices = laws.choices[batch.wall[from]];
    std::uint32_t to = from + 1;
    while (to < batch.count && laws.choices[batch.wall[to]] == choices) ++to;
    law_instance<WallBatchLaw>(choices)(batch, from, to, columns, body, history, dt);
    from = to;
  }
}

}  // namespace

void collect_wall_contacts(std::uint32_t i, const Particles& p, const std::vector<Wall>& wall_objects, WallList& list,
                           WallBatch& batch) {
  const Vec3 xi = p.position[i];
  const double ri = p.radius[i];
  const std::uint32_t* wall_of = list.wall.data();
  ContactHistory* whist = list.history.data();
  Vec3* wforce = list.force.data();
  const Wall* walls = wall_objects.data();

  const std::uint32_t k0 = list.first[i], count = list.first[i + 1] - k0;
  {  // The candidate arrays are read in order but sparsely (particles near walls only): prefetched.
    const std::size_t ahead = std::min<std::size_t>(k0 + 16, list.wall.size() - 1);
    __builtin_prefetch(&wall_of[ahead]);
    __builtin_prefetch(&whist[ahead], 1);
    __builtin_prefetch(&wforce[ahead], 1);
  }
  WallProximity near[kMaxWallCandidates];
  bool touching[kMaxWallCandidates];
  std::uint32_t touching_count = 0;
  for (std::uint32_t c = 0; c < count; ++c) {
    near[c] = wall_proximity(walls[wall_of[k0 + c]], xi);
    touching[c] = near[c].distance < ri;
    touching_count += touching[c] ? 1 : 0;
  }
  const bool several = touching_count > 1;
  for (std::uint32_t c = 0; c < count; ++c) {
    const std::uint32_t k = k0 + c;
    if (!touching[c] ||
        (several && edge_contact_hidden(c, near, touching, count,
                                        [&](std::size_t b) -> const Wall& { return walls[wall_of[k0 + b]]; },
                                        1e-6 * ri))) {
      if (whist[k].flags != 0) whist[k].reset();
      wforce[k] = Vec3{};
      continue;
    }
    const Wall& wall = walls[wall_of[k]];
    const std::uint32_t q = batch.count++;
    batch.particle[q] = i;
    batch.candidate[q] = k;
    batch.wall[q] = wall_of[k];
    const Vec3 lever = near[c].point - wall.origin;
    for (int a = 0; a < 3; ++a) {
      batch.normal[a][q] = near[c].normal[a];
      batch.point[a][q] = lever[a];
      batch.wall_velocity[a][q] = wall.current_velocity[a];
    }
    batch.distance[q] = near[c].distance;
  }
}

void wall_forces(WallBatch& batch, const WallLaws& laws, Particles& p, WallList& list, double dt, Vec3* load,
                 double& max_overlap) {
  if (batch.count == 0) return;
  const BodyArrays body{p.radius.data(), p.mass.data(), p.inv_inertia.data(), p.velocity.data(),
                        p.angular_velocity.data()};
  ContactHistory* whist = list.history.data();
  wall_law_over_batch(batch, laws, body, whist, dt);
  Vec3* wforce = list.force.data();
  Vec3 fi{}, ti{};
  for (std::uint32_t q = 0; q < batch.count; ++q) {
    const std::uint32_t i = batch.particle[q], k = batch.candidate[q], wall = batch.wall[q];
    max_overlap = std::max(max_overlap, (p.radius[i] - batch.distance[q]) / p.radius[i]);
    whist[k].tangential_spring = {batch.spring[0][q], batch.spring[1][q], batch.spring[2][q]};
    whist[k].rolling_spring = {batch.rolling_spring[0][q], batch.rolling_spring[1][q], batch.rolling_spring[2][q]};
    whist[k].flags = batch.flags[q];
    const Vec3 force{batch.force[0][q], batch.force[1][q], batch.force[2][q]};
    wforce[k] = force;
    load[2 * wall] -= force;
    load[2 * wall + 1] -= cross(Vec3{batch.point[0][q], batch.point[1][q], batch.point[2][q]}, force);
    fi += force;
    ti += Vec3{batch.torque[0][q], batch.torque[1][q], batch.torque[2][q]};
    if (q + 1 == batch.count || batch.particle[q + 1] != i) {
      p.force[i] += fi;
      p.torque[i] += ti;
      fi = Vec3{};
      ti = Vec3{};
    }
  }
  batch.count = 0;
}

}  // namespace trapdem
