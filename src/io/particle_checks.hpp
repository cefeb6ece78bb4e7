#pragma once
// What the readers of the project's own files (snapshots, checkpoints) check in the particle arrays
// they read, as the input readers check a packing: a damaged file is named, never read on as a
// silent substitute (a NaN position that spreads through an analysis, a 1e30 m/s velocity that a
// resumed run blames on the time step).
#include <cstdint>
#include <string>
#include <vector>

#include "dem/rigid/quaternion.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// m/s: no granular flow trapdem runs comes near it (a fall at the configuration's
// 1000 g bound, over the 10 m length bound, reaches ~440 m/s); a speed beyond it, or a
// spin whose surface speed is beyond it, is a damaged value.
inline constexpr double kMaxReadSpeed = 1.0e4;

// The particle rows read from `where` (a file and group, as Hdf5Group::describe gives it): ids
// non-negative and (with `distinct_ids`: not for a rank's checkpoint, whose ghosts may repeat an owned
// particle's id as its periodic image) distinct, positions and radii finite, radii positive, velocities (if given, else
// empty) finite and below kMaxReadSpeed, angular velocities (same) finite with |w| r below it.
// Throws FileError naming `where`, the row, the particle id, the value and what was expected.
void check_particle_rows(const std::string& where, const std::vector<std::int64_t>& id, const std::vector<Vec3>& position,
                         const std::vector<double>& radius, const std::vector<Vec3>& velocity,
                         const std::vector<Vec3>& angular_velocity, bool distinct_ids = true);

// A per-particle array of positive finite numbers (masses, inverse masses and inertias) or of finite
// vectors (forces, torques): the same error form, naming the array. `row` names what a row is
// ("particle", or "body" for the rigid bodies' arrays).
void check_positive_column(const std::string& where, const char* column, const std::vector<std::int64_t>& id,
                           const std::vector<double>& values, const char* row = "particle");
void check_finite_column(const std::string& where, const char* column, const std::vector<std::int64_t>& id,
                         const std::vector<Vec3>& values, const char* row = "particle");

// The rigid bodies' rows (clumps) read from `where`: ids non-negative and distinct, centres of mass
// finite, velocities finite and below kMaxReadSpeed, orientations finite unit quaternions (to 1e-6:
// the engine renormalises them every step, so more is damage, not round-off). Same error form,
// naming the body id.
void check_body_rows(const std::string& where, const std::vector<std::int64_t>& id, const std::vector<Vec3>& position,
                     const std::vector<Vec3>& velocity, const std::vector<Quaternion>& orientation);

// The bodies' members in CSR form (rigid/rigid_bodies.hpp) against the particles read beside them:
// first_member starts at 0, grows by at least one member per body and ends at member_id's length,
// and the members are the particles, each exactly once (in a run with bodies every particle is a
// member of one). Throws FileError naming `where` and the first body or id at fault.
void check_body_members(const std::string& where, const std::vector<std::int64_t>& body_id,
                        const std::vector<std::uint32_t>& first_member, const std::vector<std::int64_t>& member_id,
                        const std::vector<std::int64_t>& particle_id);

}  // namespace trapdem
