#pragma once
// Helpers of the MPI tests: the rank count, and one run's particles set beside another's by id.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <string>

#include "../dem/test_support.hpp"
#include "dem/simulation.hpp"
#include "parallel/gather.hpp"
#include "parallel/slab_decomposition.hpp"

namespace trapdem::testing_support {

inline int world_size() {
  int n = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &n);
  return n;
}
inline int world_rank() {
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}

// report() (test_support.hpp) on rank 0 only.
template <class... Args>
void root_report(fmt::format_string<Args...> format, Args&&... args) {
  if (world_rank() == 0) report(format, std::forward<Args>(args)...);
}

// The largest difference of force, torque, position and velocity between two runs' particles
// (the same ids, both in id order), each over the largest magnitude of that quantity in `serial`.
struct Difference {
  double force = 0.0, torque = 0.0, position = 0.0, velocity = 0.0;
  double force_scale = 0.0, torque_scale = 0.0;  // N, N m: the largest in the serial run
};
inline Difference difference(const Particles& decomposed, const Particles& serial) {
  Difference d;
  double v_scale = 0.0;
  for (std::size_t i = 0; i < serial.size(); ++i) {
    d.force_scale = std::max(d.force_scale, norm(serial.force[i]));
    d.torque_scale = std::max(d.torque_scale, norm(serial.torque[i]));
    v_scale = std::max(v_scale, norm(serial.velocity[i]));
  }
  for (std::size_t i = 0; i < serial.size() && i < decomposed.size(); ++i) {
    d.force = std::max(d.force, norm(decomposed.force[i] - serial.force[i]) / d.force_scale);
    d.torque = std::max(d.torque, norm(decomposed.torque[i] - serial.torque[i]) / d.torque_scale);
    d.position = std::max(d.position, norm(decomposed.position[i] - serial.position[i]));
    d.velocity = std::max(d.velocity, norm(decomposed.velocity[i] - serial.velocity[i]) / v_scale);
  }
  return d;
}

// Every particle's id once, in the same order in both.
inline void expect_same_ids(const Particles& decomposed, const Particles& serial) {
  ASSERT_EQ(decomposed.size(), serial.size());
  for (std::size_t i = 0; i < serial.size(); ++i) ASSERT_EQ(decomposed.id[i], serial.id[i]) << "at " << i;
}

inline Particles sorted_by_id(const Particles& p) {
  std::vector<std::uint32_t> order(p.size());
  for (std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return p.id[a] < p.id[b]; });
  Particles out = p;
  out.permute(order);
  return out;
}

// The decomposed run's particles (gathered from every rank) against the one-process run's.
inline Difference compare_with_serial(const Simulation& decomposed, const Simulation& serial) {
  const Particles all = gather_particles(decomposed, MPI_COMM_WORLD);
  const Particles reference = sorted_by_id(serial.particles());
  expect_same_ids(all, reference);
  return difference(all, reference);
}

}  // namespace trapdem::testing_support
