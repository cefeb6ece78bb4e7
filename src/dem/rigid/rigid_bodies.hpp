#pragma once
// Rigid bodies made of member spheres (clumps, issue 39): the bodies' state as a structure of
// arrays, beside the particles (particles.hpp) that are their members. A member is an ordinary
// particle for the lists and the force back end (every contact law, walls included); the engine
// leaves out the pairs of two members of one body, sums the members' forces onto their body and
// moves the body (body_motion.hpp), and the members with it.
//
// In a run with bodies every particle is a member of exactly one body (a lone sphere is a body of
// one member): the step integrates bodies, not particles. A member particle carries its body's mass
// (the contact's effective mass, so the dashpot's restitution holds for body-body impacts, as
// LIGGGHTS's multisphere does) and the inverse of its body's mean principal moment (read only by
// the rolling models' inertias; shapes stand in for rolling resistance, so clumps are run without it).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "dem/particles.hpp"
#include "dem/rigid/clump_template.hpp"
#include "dem/rigid/quaternion.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

inline constexpr std::uint32_t kNoBody = ~0u;

// A symmetric 3x3 matrix by its six entries: a body's inverse inertia tensor in the space frame.
struct SymmetricMatrix3 {
  double xx = 0.0, yy = 0.0, zz = 0.0, xy = 0.0, xz = 0.0, yz = 0.0;
  Vec3 operator*(const Vec3& v) const {
    return {xx * v.x + xy * v.y + xz * v.z, xy * v.x + yy * v.y + yz * v.z, xz * v.x + yz * v.y + zz * v.z};
  }
  bool operator==(const SymmetricMatrix3&) const = default;
};

struct RigidBodies {
  // Per body.
  std::vector<std::int64_t> id;             // stable identity
  std::vector<double> mass;                 // kg
  std::vector<double> volume;               // m^3, of the union of the members (the grain's size)
  std::vector<Vec3> principal_inertia;      // kg m^2, about the body frame's axes (principal ones)
  std::vector<Vec3> position;               // m, the centre of mass
  std::vector<Vec3> velocity;               // m/s, of the centre of mass
  std::vector<Quaternion> orientation;      // body frame to space frame
  std::vector<Vec3> angular_momentum;       // kg m^2/s, about the centre of mass, space frame
  std::vector<Vec3> force;                  // N, the members' contact forces summed (gravity not included)
  std::vector<Vec3> torque;                 // N m, about the centre of mass
  std::vector<std::uint32_t> first_member{0};  // body b's members: [first_member[b], first_member[b + 1])
  // Per member, in body order.
  std::vector<std::int64_t> member_id;  // the member sphere's particle id
  std::vector<Vec3> member_offset;      // m, its centre in the body frame

  // Derived, not state: where each member is in the particle arrays and each particle's body
  // (kNoBody when it has none), after every re-ordering of the particles (locate_members).
  std::vector<std::uint32_t> member_particle;
  std::vector<std::uint32_t> body_of_particle;
  // Workspaces of the step (body_motion.cpp), valid from a placement of the members to the next
  // turn of the bodies: each member's arm (m, centre of mass to its centre, space frame) and each
  // body's inverse inertia tensor in the space frame (kg^-1 m^-2, J = R I^-1 R^T: the angular
  // velocity is J L; the second half kick reuses it, as the kick turns no body).
  std::vector<Vec3> arm;
  std::vector<SymmetricMatrix3> inverse_inertia;

  std::size_t size() const { return id.size(); }
  bool empty() const { return id.empty(); }
  std::size_t member_count() const { return member_id.size(); }

  Vec3 angular_velocity(std::size_t b) const;  // rad/s, space frame
  // m, from body b's centre of mass to its member m's centre, space frame.
  Vec3 member_arm(std::size_t b, std::size_t m) const { return rotate(orientation[b], member_offset[m]); }
  std::size_t body_of_member(std::size_t member) const;  // binary search (tools, tests)

  // Finds each member among `particle_id` (the particles' ids, in their current order). Throws
  // SimulationError when a member is missing or a particle belongs to no body.
  void locate_members(const std::vector<std::int64_t>& particle_id);

  // After the particles were permuted (Particles::permute(order): the particle now at i was at
  // order[i]): the derived arrays follow the permutation (no search), and the bodies are put in
  // the order of their first member, so that the body loops (body_motion.cpp) walk the particle
  // arrays about in order and a thread's block of bodies holds about the members of its block of
  // particles. Every per-body array and the members' arrays move with their body; nothing a step
  // computes depends on the bodies' order.
  void follow_particle_permutation(const std::vector<std::uint32_t>& order);

  void clear();
};

// Appends a body of `shape` (a template scaled to its size, clump_template.hpp) of solid density
// `density` (kg/m^3) with its centre of mass at `position`, orientation `orientation`, velocity and
// angular velocity (space frame), and its members as particles with ids first_member_id, +1, ...
// Returns the body's index. The members' positions and velocities follow from the body's. The
// derived arrays are extended for the appended members (current if they were).
std::size_t add_rigid_body(RigidBodies& bodies, Particles& particles, std::int64_t body_id,
                           std::int64_t first_member_id, const ClumpTemplate& shape, double density,
                           const Vec3& position, const Quaternion& orientation, const Vec3& velocity = {},
                           const Vec3& angular_velocity = {});

// kg, the mass that sets the time scale of a body's contacts (the critical step): a contact force
// at arm `reach` (m) from the centre of mass turns the body about its least principal moment
// I_min (kg m^2) like a mass I_min / reach^2 on the spring (a torsional oscillator,
// T = 2 pi sqrt(I / (k reach^2))); the smaller of that and the body's mass.
double contact_time_scale_mass(double mass, const Vec3& principal_inertia, double reach);

// What sets body b's critical step (Simulation::critical_time_step): a contact force on a member
// turns the body too, at most at the farthest reach of a member's surface from the centre of mass
// (contact_time_scale_mass), on the stiffness of its smallest member. The members' radii are
// `particles`' (the derived member_particle current).
struct BodyContactScale {
  double mass = 0.0;             // kg
  double smallest_radius = 0.0;  // m
};
BodyContactScale body_contact_scale(const RigidBodies& bodies, const Particles& particles, std::size_t b);

// Removes the pairs of two members of one body from a half list (pair_list.hpp) whose particles'
// bodies `body_of_particle` gives: a body's members do not touch each other.
struct PairList;
void exclude_pairs_within_bodies(PairList& pairs, const std::vector<std::uint32_t>& body_of_particle);

}  // namespace trapdem
