#pragma once
// The rotation of a rigid body over a time step, by the symmetric splitting of the free rotor into
// rotations about its principal axes: NO_SQUISH (Miller, Eleftheriou, Pattnaik, Ndirango, Newns &
// Martyna 2002, "Symplectic quaternion scheme for biophysical molecular dynamics", J. Chem. Phys.
// 116, 8649). With the angular momentum kicked by the torque in the space frame for half a step
// before and after (as the translation's velocity Verlet), the step is second order, time-reversible
// and symplectic: each sub-rotation keeps the space-frame angular momentum exactly (and the
// quaternion's norm, renormalised against round-off), and the energy's error stays bounded, of
// order dt^2, without drift.
//
// A symmetric top (two equal principal moments: a dimer, any body of revolution, and a spherical
// one) takes instead the exact solution of the torque-free motion (Landau & Lifshitz, Mechanics,
// sec. 33): the body precesses about L at |L| / I_perp while spinning about its symmetry axis at
// L_axis (1/I_axis - 1/I_perp) relative to that, R(t) = R0 Rot(L_body, |L| t / I_perp)
// Rot(e_axis, L_axis (1/I_axis - 1/I_perp) t). Two turns instead of five, and no splitting error;
// between the half kicks the step is then the free rotor's exact flow, as symplectic and
// time-reversible as the splitting. The equal moments are equal bit for bit: a symmetric shape's
// template makes them so (clump_template.cpp).
#include "dem/rigid/quaternion.hpp"
#include "dem/vec3.hpp"

namespace trapdem {

// The free rotation of a body with principal moments `inertia` (kg m^2, the body frame's axes
// principal) over `dt` (s): its orientation `q` and its angular momentum in the body frame
// `momentum_body` (kg m^2/s) are advanced by R3(dt/2) R2(dt/2) R1(dt) R2(dt/2) R3(dt/2), R_k(h) the
// exact rotation about body axis k at angular velocity L_k / I_k for a time h; or a symmetric top's
// exact turn (above).
void rotate_freely(Quaternion& q, Vec3& momentum_body, const Vec3& inertia, double dt);

// rotate_freely for `count` bodies at once (at most kRotationLanes), lane by lane the same
// arithmetic, so that the compiler runs the bodies side by side in SIMD registers: a free rotation
// is a chain of ~100 dependent operations, which one body at a time leaves the core waiting on
// latencies. Each body agrees with rotate_freely to round-off (the lanes may fuse multiply-adds
// differently); a body whose step turns it by 0.01 rad or more, or whose kind (a symmetric top about
// an axis, or not a top) differs from the first body's, takes rotate_freely itself.
inline constexpr int kRotationLanes = 4;
void rotate_freely_lanes(Quaternion* q, Vec3* momentum_body, const Vec3* inertia, double dt, int count);

// The body axis of a symmetric top's odd moment: 0 when I_y == I_z (a prolate body such as a dimer,
// with moments ascending, or a spherical one), 2 when I_x == I_y (oblate), 1 when I_x == I_z; -1
// when no two moments are equal (NO_SQUISH).
int symmetry_axis(const Vec3& inertia);

// The body's angular velocity in the space frame from its angular momentum in the body frame.
Vec3 angular_velocity_space(const Quaternion& q, const Vec3& momentum_body, const Vec3& inertia);

}  // namespace trapdem
