#pragma once
// Engine checkpoints: everything a Simulation needs to continue bit for bit (particles with their
// forces, the Verlet lists with every contact's history, time, counters, wall states), plus a
// free-form string map for the caller's own state (stage, progress, experiment bookkeeping).
// Written atomically (io/atomic_file.hpp): a failed write leaves the previous checkpoint intact.
// Layout: docs/output.md, "checkpoint.h5".
#include <filesystem>
#include <map>
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

struct Checkpoint {
  Particles particles;
  Simulation::ListState lists;
  double time = 0.0;                 // s
  double time_step = 0.0;            // s, checked on restore: another step would not continue the run
  SimulationStats stats;
  std::vector<WallState> walls;
  std::map<std::string, std::string> metadata;  // the caller's: "stage" = "lowering", ...
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
// Throws InputError if the walls or the time step differ (the resumed run would silently diverge).
void restore_checkpoint(Simulation& simulation, Checkpoint checkpoint);

}  // namespace trapdem
