#pragma once
// Engine checkpoints: everything a Simulation needs to continue bit for bit (particles with their
// forces, the rigid bodies of a run of clumps, the Verlet lists with every contact's history, time,
// counters, wall states), plus a free-form string map for the caller's own state (stage, progress,
// experiment bookkeeping).
// Written atomically (io/atomic_file.hpp): a failed write leaves the previous checkpoint intact.
// Layout: docs/output.md, "checkpoint.h5".
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "dem/simulation.hpp"
#include "core/errors.hpp"

namespace trapdem {

// What a Wall carries that changes during a run. The rest (shape, law, prescribed velocity) comes
// from the configuration that builds the Simulation again.
struct WallState {
  std::string name;
  Vec3 origin;             // m
  Vec3 displacement;       // m
  Vec3 force;              // N, load of the last step
  Vec3 torque;             // N m, about origin
  Vec3 current_velocity;   // m/s
};

// One rank's own state in a checkpoint of a run on several ranks: with it the rank continues bit
// for bit on the same rank count.
struct RankState {
  Particles particles;              // the rank's owned particles, then its ghosts, in its order
  std::size_t ghosts = 0;
  Simulation::ListState lists;      // indices into `particles`
  std::vector<std::uint8_t> decomposition;  // the decomposition's own state (src/parallel's format)
};

struct Checkpoint {
  Particles particles;
  // The rigid bodies (clumps) whose members the particles are; empty in a run of spheres (and in a
  // file written before checkpoints held bodies). State only: the derived arrays (member_particle,
  // body_of_particle) and the step's workspaces are left empty, as restore() finds them again.
  RigidBodies bodies;
  Simulation::ListState lists;
  double time = 0.0;                 // s
  double time_step = 0.0;            // s, checked on restore: another step would not continue the run
  SimulationStats stats;
  std::vector<WallState> walls;
  std::map<std::string, std::string> metadata;  // the caller's: "stage" = "lowering", ...
  // A run on several ranks (src/parallel writes it): `particles` holds every rank's owned
  // particles in id order and `lists` is empty; the contact histories are kept by ids, so that a
  // resume on any rank count (one process too) rebuilds the lists with them; `ranks` holds each
  // rank's own state, for a resume on the same rank count.
  std::optional<HistoryArchive> histories;
  std::vector<RankState> ranks;
};

// Copies the simulation's state. Take it between steps (after step() or run()): a Simulation whose
// particles were just added or removed holds lists that the next step rebuilds; restore_checkpoint
// handles added particles (it lets the next step rebuild too) but not removed ones (the engine's
// pending history is not part of ListState).
Checkpoint capture_checkpoint(const Simulation& simulation, std::map<std::string, std::string> metadata = {});

// Writes atomically; throws FileError naming the path (the previous file at `path` stays).
void write_checkpoint(const std::filesystem::path& path, const Checkpoint& checkpoint);
inline void save_checkpoint(const std::filesystem::path& path, const Simulation& simulation,
                            std::map<std::string, std::string> metadata = {}) {
  write_checkpoint(path, capture_checkpoint(simulation, std::move(metadata)));
}

// Reads a checkpoint; throws FileError (missing, damaged or not a trapdem checkpoint).
Checkpoint read_checkpoint(const std::filesystem::path& path);

// Puts the checkpoint into a Simulation constructed as the checkpointed one was (same settings,
// laws and walls added in the same order, gravity and wall velocities set as functions of time).
// Throws InputError if the walls or the time step differ (the resumed run would silently diverge),
// or if the simulation was built with rigid bodies and the checkpoint holds none. The checkpoint's
// bodies replace the simulation's (Simulation::restore_bodies, before its particles and lists).
// A checkpoint with histories by ids (a run on several ranks) puts every particle into the
// simulation and lets its next step rebuild the lists (on a decomposition: each rank keeps its
// share, Simulation::resume_from_histories).
void restore_checkpoint(Simulation& simulation, Checkpoint checkpoint);
// The walls and time step of the checkpoint checked against the simulation's, and its wall states
// put into it (the part of restore_checkpoint every rank count shares).
void restore_walls(Simulation& simulation, const Checkpoint& checkpoint);

}  // namespace trapdem
