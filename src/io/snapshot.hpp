#pragma once
// Particle snapshots for analysis and viewing: snapshots.h5 holds one group per snapshot
// (/snapshots/000000, /snapshots/000001, ...) and snapshots.xmf, its XDMF 3 companion, lets
// ParaView open the file as a time series of particles. Layout: docs/output.md.
//
// Appending never rewrites what is already written, and never leaves a broken file: each
// snapshot is a file of its own, snapshots/000003.h5 beside snapshots.h5, written to a temporary
// sibling, synced and renamed into place (io/atomic_file.hpp); snapshots.h5 is then a small index,
// rewritten the same way, whose /snapshots/000003 is an HDF5 external link to that file's root
// (h5py and the HDF5 library follow it like a group). A kill or a full disk at any point leaves
// the previous index, naming only complete files. Readers also accept files whose snapshots are
// plain groups inside snapshots.h5 (other tools; trapdem before format version 2).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "dem/particles.hpp"
#include "dem/rigid/quaternion.hpp"
#include "dem/rigid/rigid_bodies.hpp"
#include "dem/vec3.hpp"
#include "core/errors.hpp"

namespace trapdem {

// The rigid bodies (clumps) of a snapshot: their centres of mass and motion, so that an analysis can
// follow the grains rather than their member spheres. Rows are bodies, in the engine's body order
// (stable across a run, bodies are only appended; match them by id all the same).
struct SnapshotBodies {
  std::vector<std::int64_t> id;
  std::vector<Vec3> position;             // m, the centre of mass
  std::vector<double> radius;             // m, volume-equivalent (the sphere of the grain's volume)
  std::vector<Vec3> velocity;             // m/s, of the centre of mass
  std::vector<Quaternion> orientation;    // body frame to space frame (w, x, y, z)
  std::vector<Vec3> angular_velocity;     // rad/s, space frame

  std::size_t size() const { return id.size(); }
  bool empty() const { return id.empty(); }
};

// Per particle of a snapshot with bodies: the id of the body it is a member of, or this (none).
inline constexpr std::int64_t kNoBodyId = -1;

struct Snapshot {
  double time = 0.0;                    // s, simulated
  std::string stage;                    // "pluviation", "settling", "spin-up", "lowering", ...
  double trapdoor_displacement = 0.0;   // m, downward travel of the trapdoor (positive down)
  std::int64_t step = 0;                // engine step count
  std::vector<std::int64_t> id;
  std::vector<Vec3> position;           // m (wrapped into the domain on periodic axes)
  std::vector<Vec3> velocity;           // m/s
  std::vector<Vec3> angular_velocity;   // rad/s
  std::vector<double> radius;           // m
  std::vector<Int3> image;              // periodic images crossed: unwrapped = position + image * length
  // A run of clumps: per particle its body's id (kNoBodyId: none), and the bodies. Both empty in a
  // run of spheres (and when read from a file written without them).
  std::vector<std::int64_t> body;
  SnapshotBodies bodies;

  std::size_t size() const { return id.size(); }
};

Snapshot make_snapshot(const Particles& particles, double time, std::string stage, double trapdoor_displacement,
                       std::int64_t step);
// The same with the rigid bodies whose members the particles are (Simulation::bodies(); empty: a
// run of spheres, the snapshot above). The particles' body ids are found by their ids, not by the
// bodies' derived arrays, so `particles` may be in any order (a gathered copy too).
Snapshot make_snapshot(const Particles& particles, const RigidBodies& bodies, double time, std::string stage,
                       double trapdoor_displacement, std::int64_t step);

// A snapshot of clumps as its grains: one row per body (its id, centre of mass, volume-equivalent
// radius, velocity and angular velocity), what the strain analysis follows. A snapshot without
// bodies is returned as it is.
Snapshot grain_view(const Snapshot& snapshot);

// One line of the file's index (no particle data).
struct SnapshotInfo {
  std::string name;                     // group name, "000003"
  double time = 0.0;                    // s
  std::string stage;
  double trapdoor_displacement = 0.0;   // m
  std::int64_t step = 0;
  std::size_t particle_count = 0;
  bool has_body = false;                // a per-particle "body" dataset (a run of clumps)
  // Where its datasets are, as the XDMF names them: "snapshots/000003.h5:/" (its own file) or
  // "snapshots.h5:/snapshots/000003/" (a group inside the index, as other tools write it).
  std::string location;
};

// Appends a snapshot to `h5_path` (creating the index if absent): writes its own file in the folder
// named as `h5_path` without extension, links it from the index and rewrites the XDMF companion
// (same name with the .xmf extension). Returns the new snapshot's group name. Throws FileError
// naming the path; the previous files stay as they were.
std::string append_snapshot(const std::filesystem::path& h5_path, const Snapshot& snapshot);

// Drops the snapshots taken after engine step `last_step` (a resumed run writes them again): the
// index and the XDMF are rewritten without them, then their files are removed. No snapshot left:
// the index and the XDMF are removed. Nothing to drop (or no index): nothing changes.
void truncate_snapshots(const std::filesystem::path& h5_path, std::int64_t last_step);
// The same by count: keeps the first `keep` snapshots of the index and drops the rest.
void keep_snapshots(const std::filesystem::path& h5_path, std::size_t keep);

// Reading (for the analysis; accepts files written by other tools that follow docs/output.md:
// id, position and radius are required, velocity, angular_velocity and image default to zero,
// missing attributes to 0 / ""; body and bodies/ are read when present, else left empty).
std::vector<SnapshotInfo> list_snapshots(const std::filesystem::path& h5_path);
Snapshot read_snapshot(const std::filesystem::path& h5_path, const std::string& name);
std::vector<Snapshot> read_snapshots(const std::filesystem::path& h5_path);

// The XDMF 3 text for `snapshots` stored in the HDF5 file named `h5_file_name` (relative to the
// .xmf file's folder): a temporal collection of Polyvertex grids, one vertex cell per particle,
// with attributes radius, id, velocity and angular_velocity, and body (its body's id) where the
// snapshot has one. The cells' vertex list is the file's /vertex_index (0, 1, 2, ...;
// `vertex_index_length` long); a snapshot with more particles than that gets points without cells.
// Snapshots without particles are left out (ParaView rejects empty grids).
std::string snapshot_xdmf(const std::string& h5_file_name, const std::vector<SnapshotInfo>& snapshots,
                          std::size_t vertex_index_length);
// Writes snapshot_xdmf(...) for the file at h5_path to h5_path with the .xmf extension, atomically.
void write_snapshot_xdmf(const std::filesystem::path& h5_path);

}  // namespace trapdem
