#pragma once
// Particle-wall contacts (engine-private): found per particle (closest point, hidden seams),
// gathered in a batch, run through the law as one vectorised loop with each wall's parameters
// gathered per contact, then stored and added in contact order.
#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/threaded_cpu/batch_lane.hpp"
#include "dem/contact/law.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"
#include "dem/wall_list.hpp"

namespace trapdem {

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

// The walls' laws, fixed at Simulation::add_wall. The batch loop gathers a contact's parameters
// from its wall's entry, so walls of different friction share one batch. They are kept as a
// generated structure of arrays: LawParams is a block of doubles, and column f holds double f of
// every wall's LawParams (a gather from an array of LawParams, 88 bytes apart, does not
// vectorise with GCC 12: "not suitable for gather load"). The choices are compiled into the loop:
// walls whose choices differ run in stretches of equal choices (`uniform` says whether they all
// agree).
struct WallLaws {
  static constexpr std::size_t kFields = sizeof(LawParams) / sizeof(double);
  static_assert(sizeof(LawParams) == kFields * sizeof(double), "LawParams must hold doubles only");
  using Row = std::array<double, kFields>;

  std::vector<LawChoices> choices;                   // per wall
  std::array<std::vector<double>, kFields> columns;  // columns[f][wall]
  bool uniform = true;

  void add(const LawParams& p, const LawChoices& c) {
    uniform = uniform && (choices.empty() || choices.front() == c);
    choices.push_back(c);
    const Row row = std::bit_cast<Row>(p);
    for (std::size_t f = 0; f < kFields; ++f) columns[f].push_back(row[f]);
  }

  // Column pointers for the batch loop.
  struct View {
    const double* column[kFields];
    [[gnu::always_inline]] LawParams of(std::uint32_t wall) const {
      Row row;
      for (std::size_t f = 0; f < kFields; ++f) row[f] = column[f][wall];
      return std::bit_cast<LawParams>(row);
    }
  };
  View view() const {
    View v;
    for (std::size_t f = 0; f < kFields; ++f) v.column[f] = columns[f].data();
    return v;
  }
};

// The wall contacts of particle i (which has walls within reach): the touching candidates go to
// the batch, the others lose their history and force.
void collect_wall_contacts(std::uint32_t i, const Particles& p, const std::vector<Wall>& walls, WallList& list,
                           WallBatch& batch);

// The law over the batch (vectorised), then in contact order: the histories and forces stored, the
// thread's wall loads `load` (force, torque per wall) and each particle's force and torque added
// (its contacts summed first). Empties the batch.
void wall_forces(WallBatch& batch, const WallLaws& laws, Particles& p, WallList& list, double dt, Vec3* load,
                 double& max_overlap);

}  // namespace trapdem
