#pragma once
// What the batch loops (pair_sweep.cpp, wall_sweep.cpp) share: the particle data they read, and a
// contact's output (its force on the first body and its new history) stored into lane q of a
// batch's arrays.
#include <cstdint>

#include "dem/contact/contact_history.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// The particle data the batch loops read.
struct BodyArrays {
  const double* __restrict radius;
  const double* __restrict mass;
  const double* __restrict inv_inertia;
  const Vec3* __restrict velocity;
  const Vec3* __restrict angular_velocity;
};

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

}  // namespace trapdem
