#pragma once
// The parallel back end as the engine sees it: the box split into sub-domains, one per process
// (rank), each rank's Simulation holding the particles of its sub-domain ("owned", indices
// [0, owned_count())) followed by ghosts, copies of other ranks' particles within the interaction
// range of the sub-domain. The engine's loops, contact law and lists are the same on every rank;
// this interface moves particles, ghosts, forces and sums between the ranks at fixed points of
// the step (Simulation::step, simulation.cpp, with the exchanges of halo.cpp). It names no message-passing
// library: the MPI implementation is src/parallel (SlabDecomposition). Without one attached the
// engine runs as a single process and calls none of this.
//
// Every call is collective: all ranks make it, in the same order.
#include <string>
#include <vector>

#include "dem/domain.hpp"
#include "dem/history_archive.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"

namespace trapdem {

class Decomposition {
 public:
  virtual ~Decomposition() = default;

  // Once, before the first step: every rank was given the same particles (possibly none, in the
  // domain); each keeps its share.
  virtual void adopt(Particles& p, const Domain& domain) = 0;
  // Whether a particle placed at x now would be this rank's (a pour inserts each particle on the
  // rank that owns its site; every rank draws the same sites).
  virtual bool owns(const Vec3& x) const = 0;

  // At a list rebuild, ghosts already dropped: particles outside this rank's sub-domain leave
  // with their contact histories (the pair records whose lower id is theirs, their wall records)
  // and those arriving are appended, theirs with them. Sub-domain boundaries may move here (load
  // balancing). `range` (m) is the interaction range the ghosts will cover.
  virtual void migrate(Particles& p, HistoryArchive& archive, double range) = 0;
  // After the owned particles are in their final order (p holds no ghost): appends the ghosts,
  // every other rank's particles within `range` (m) of this sub-domain. Returns how many.
  virtual std::size_t exchange_ghosts(Particles& p, double range) = 0;
  // Each step without a rebuild: the ghosts' positions and velocities from their owners.
  virtual void update_ghosts(Particles& p) = 0;
  // After the contact sweep: the forces and torques the ghosts received, added to their owners'
  // (in a fixed order).
  virtual void return_ghost_forces(Particles& p) = 0;

  // Global reductions. `sum` and the wall loads add the ranks' values in rank order, so a given
  // rank count gives the same numbers every time.
  virtual bool any(bool local) = 0;
  virtual void max(double* values, int count) = 0;  // each value: its largest over the ranks
  double max(double local) {
    max(&local, 1);
    return local;
  }
  virtual double sum(double local) = 0;
  virtual void sum_wall_loads(std::vector<Wall>& walls) = 0;  // force and torque: the ranks' sums

  // Returns when no rank failed (every `message` empty); else throws SimulationError on every rank
  // with the message of the lowest failing rank, so a failure stops all ranks and none waits.
  virtual void agree_on_failure(const std::string& message) = 0;

  virtual int rank() const = 0;
  virtual int ranks() const = 0;
};

}  // namespace trapdem
