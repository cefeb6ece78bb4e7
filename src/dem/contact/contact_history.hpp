#pragma once
// What a contact remembers between steps.
#include <cstdint>

#include "dem/vec3.hpp"

namespace trapdem {

// Owned by the pair (the engine's compact array of touching pairs, see Simulation) or by the
// particle-wall candidate; expressed for side i (a flipped pair negates the vectors,
// HistoryArchive).
struct ContactHistory {
  Vec3 tangential_spring;     // m, accumulated tangential displacement (seed eq. 2's integral)
  Vec3 rolling_spring;        // N m, elastic rolling torque of the EPSD model
  std::uint32_t flags = 0;    // kTouching | kSliding

  static constexpr std::uint32_t kTouching = 1u;
  static constexpr std::uint32_t kSliding = 2u;
  bool touching() const { return flags & kTouching; }
  bool sliding() const { return flags & kSliding; }
  void reset() { *this = ContactHistory{}; }
};

}  // namespace trapdem
