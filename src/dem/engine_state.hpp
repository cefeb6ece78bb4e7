#pragma once
// The engine's state, declared once (as Cabana declares its particle arrays once and the library
// owns the loops): what a step reads and writes. Simulation owns one; it integrates the particles,
// moves the walls and builds the lists, and hands the whole state to its force back end
// (force_backend.hpp), which reads the particles, the lists and last step's contact histories and
// writes the forces, torques, this step's histories and the walls' loads. A back end keeps nothing
// of the run's state itself (only workspaces), so a checkpoint of this state resumes on any back end.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/pair_histories.hpp"
#include "dem/pair_list.hpp"
#include "dem/particles.hpp"
#include "dem/rigid/rigid_bodies.hpp"
#include "dem/vec3.hpp"
#include "dem/wall.hpp"
#include "dem/wall_list.hpp"

namespace trapdem {

// The neighbour lists with the contact histories, in the engine's compact form.
struct ContactLists {
  // The half list of particle pairs (pair_list.hpp), in the particles' cell order. Its `history` is
  // empty while the engine runs: the touching pairs' histories are in `contacts`.
  PairList pairs;
  // Per listed pair, its index into `contacts`, or kNoContact (most listed pairs do not touch).
  ContactSlots pair_contact;
  // The touching pairs' histories of the last force pass; a pass writes its own into
  // `contacts_next`, in pair order (a thread's block from index pairs.first[begin] on), renumbers
  // `pair_contact` and swaps the two. Both hold an empty entry at index pairs.size(): where a
  // contact that has just formed reads its history from.
  PairHistories contacts, contacts_next;
  // The particle-wall candidates with their histories and last forces (wall_list.hpp).
  WallList walls;
  // The particles with a wall candidate, ascending.
  std::vector<std::uint32_t> particles_near_walls;
  // Per particle i: one past the highest partner of the owners below i (0 when none). A back end
  // that kicks each particle as soon as its force is complete knows from it which particles may
  // still receive a share from an earlier block.
  std::vector<std::uint32_t> partner_reach;
  // What the rebuild criterion compares with (Simulation::lists_outdated): the positions (m) and
  // the walls' displacements (m) at the last build, and the skin (m) the lists were built with
  // (a change of skin takes effect at the next build; the lists stay exact until then).
  std::vector<Vec3> position_at_build;
  std::vector<Vec3> wall_displacement_at_build;
  double skin_at_build = 0.0;
};

struct EngineState {
  // The owned particles first ([0, owned())), then, on a rank of a decomposition, the ghosts
  // (copies of other ranks' particles, whose forces a pass computes as shares to send back).
  Particles particles;
  std::size_t ghosts = 0;
  // Rigid bodies (clumps, rigid/rigid_bodies.hpp). None: every particle is a free sphere. Else every
  // particle is a member of one body, and the step moves the bodies (rigid/body_motion.hpp); a force
  // back end sees only the member spheres.
  RigidBodies bodies;
  std::vector<Wall> walls;  // with the loads (force, torque) the last force pass summed
  ContactLists lists;

  std::size_t owned() const { return particles.size() - ghosts; }
};

}  // namespace trapdem
