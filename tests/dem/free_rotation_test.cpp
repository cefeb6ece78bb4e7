// The rigid body's rotation (src/dem/rigid/free_rotation.hpp, issue 39): NO_SQUISH's splitting
// against the torque-free rigid body's exact properties (Landau & Lifshitz, Mechanics, sec. 33 and
// 37): space-frame angular momentum conserved and the energy's error bounded, second-order
// convergence, and the intermediate axis unstable; the symmetric top's exact turn at
// Omega = (I3 - I1) / I1 w3 and its precession about L at any step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dem/rigid/free_rotation.hpp"
#include "test_support.hpp"

using namespace trapdem;

namespace {

double energy(const Vec3& L, const Vec3& I) { return 0.5 * (L.x * L.x / I.x + L.y * L.y / I.y + L.z * L.z / I.z); }

}  // namespace

// An asymmetric body (I = 1, 2, 3 kg m^2), 100 000 steps of 1 ms (about 20 turns): each
// sub-rotation keeps the space-frame angular momentum exactly, so only round-off remains there
// (1e-11 relative: 5e5 rotations of ~1e-16 each); the energy's error is bounded, of order dt^2
// (below 1e-6 here), and does not drift: the second half's largest error is no larger than the
// first half's (within 10 %), as a symplectic scheme's.
TEST(FreeRotation, AngularMomentumConservedEnergyBounded) {
  const Vec3 I{1.0, 2.0, 3.0};
  Quaternion q = normalised({0.9, 0.1, -0.3, 0.2});
  Vec3 L{0.7, -1.1, 0.9};
  const Vec3 L_space = rotate(q, L);
  const double E = energy(L, I);
  double worst_first = 0.0, worst_second = 0.0;
  for (int s = 0; s < 100000; ++s) {
    rotate_freely(q, L, I, 1e-3);
    const double error = std::abs(energy(L, I) / E - 1.0);
    (s < 50000 ? worst_first : worst_second) = std::max(s < 50000 ? worst_first : worst_second, error);
  }
  EXPECT_LT(std::max(worst_first, worst_second), 1e-6);
  EXPECT_LT(worst_second, 1.1 * worst_first);
  const Vec3 after = rotate(q, L);
  EXPECT_NEAR(norm(after - L_space) / norm(L_space), 0.0, 1e-11);
  EXPECT_NEAR(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z, 1.0, 1e-14);
}

// A symmetric top (I1 = I2 = 1, I3 = 2) spinning at w3 = 1 rad/s with w1 = 0.3 takes the exact
// solution: in the body frame (w1, w2) turns at Omega = (I3 - I1) / I1 w3 = 1 rad/s (Euler's
// equations), and in space the symmetry axis precesses about L at |L| / I1 (Landau & Lifshitz,
// sec. 33). After 10 s, at a step of 1 ms (the series) and of 0.25 s (2.6 rad a step: the library's
// sin and cos), both agree with the closed form to round-off (1e-11: 10^4 steps of ~1e-16).
TEST(FreeRotation, SymmetricTopTurnsExactlyAtAnyStep) {
  const Vec3 I{1.0, 1.0, 2.0};
  ASSERT_EQ(symmetry_axis(I), 2);
  const Quaternion q0 = normalised({0.9, 0.1, -0.3, 0.2});
  const Vec3 L0{0.3 * I.x, 0.0, 1.0 * I.z};  // body frame
  const Vec3 L_space = rotate(q0, L0);
  const Vec3 axis0 = rotate(q0, Vec3{0.0, 0.0, 1.0});
  for (const double dt : {1e-3, 0.25}) {
    Quaternion q = q0;
    Vec3 L = L0;
    const int steps = int(std::lround(10.0 / dt));
    for (int s = 0; s < steps; ++s) rotate_freely(q, L, I, dt);
    const double phase = std::atan2(L.y / I.y, L.x / I.x);
    EXPECT_NEAR(std::remainder(phase - 10.0, 2.0 * M_PI), 0.0, 1e-11) << "dt " << dt;
    // The symmetry axis turned about L by |L| t / I1 (Rodrigues' formula).
    const Vec3 u = L_space / norm(L_space);
    const double angle = norm(L_space) * 10.0 / I.x;
    const Vec3 expected = axis0 * std::cos(angle) + cross(u, axis0) * std::sin(angle) + u * dot(u, axis0) * (1.0 - std::cos(angle));
    EXPECT_LT(norm(rotate(q, Vec3{0.0, 0.0, 1.0}) - expected), 1e-11) << "dt " << dt;
    EXPECT_LT(norm(rotate(q, L) - L_space) / norm(L_space), 1e-12) << "dt " << dt;
  }
}

// NO_SQUISH on an asymmetric body (I = 1, 2, 3) is second order: the orientation after 2 s, against
// a run at a 64 times smaller step, is off by 4 times less when the step is halved (within 10 %).
TEST(FreeRotation, AsymmetricBodyConvergesToSecondOrder) {
  const Vec3 I{1.0, 2.0, 3.0};
  ASSERT_EQ(symmetry_axis(I), -1);
  const auto turned = [&](double dt) {
    Quaternion q = normalised({0.9, 0.1, -0.3, 0.2});
    Vec3 L{0.7, -1.1, 0.9};
    const int steps = int(std::lround(2.0 / dt));
    for (int s = 0; s < steps; ++s) rotate_freely(q, L, I, dt);
    return q;
  };
  const Quaternion reference = turned(1e-3 / 64.0);
  const auto error = [&](const Quaternion& q) {
    const double sign = q.w * reference.w + q.x * reference.x + q.y * reference.y + q.z * reference.z < 0.0 ? -1.0 : 1.0;
    return std::hypot(std::hypot(sign * q.w - reference.w, sign * q.x - reference.x),
                      std::hypot(sign * q.y - reference.y, sign * q.z - reference.z));
  };
  const double coarse = error(turned(1e-3)), fine = error(turned(5e-4));
  EXPECT_GT(coarse, 1e-9);  // a splitting error to measure, far above round-off
  EXPECT_NEAR(coarse / fine, 4.0, 0.4);
}

// Spin about the largest or smallest principal axis is stable; about the intermediate one a small
// disturbance grows until the body flips (the "tennis racket" theorem).
TEST(FreeRotation, IntermediateAxisUnstable) {
  const Vec3 I{1.0, 2.0, 3.0};
  const auto least_alignment = [&](int axis) {
    Quaternion q;
    Vec3 L{1e-3, 1e-3, 1e-3};
    L[axis] = I[axis] * 1.0;
    double least = 1.0;
    for (int s = 0; s < 40000; ++s) {  // 40 s, many growth times of the unstable mode
      rotate_freely(q, L, I, 1e-3);
      least = std::min(least, L[axis] / norm(L));
    }
    return least;
  };
  EXPECT_GT(least_alignment(0), 0.99);
  EXPECT_GT(least_alignment(2), 0.99);
  EXPECT_LT(least_alignment(1), 0.0);  // it turned over
}

// The lanes' rotation (several bodies side by side) against rotate_freely one body at a time:
// seven bodies of different inertias and momenta in groups of four and three, one of them turning
// 0.05 rad a step (past the series: it takes rotate_freely itself), over 2000 steps. Tolerance
// 1e-12: the lanes may fuse multiply-adds differently (~1e-16 a step, growing with the steps as
// rounding does in a rotation, ~sqrt(steps) to steps x that); a wrong sign or axis in one lane's
// product is off by the whole turn (1e-2 and more).
namespace {

// Bodies (q, L, I) turned 2000 steps of 1 ms in groups of kRotationLanes by rotate_freely_lanes and
// one at a time by rotate_freely: each body's quaternion and momentum must agree within 1e-12.
void expect_lanes_agree_with_one_at_a_time(std::vector<Quaternion> q, std::vector<Vec3> L, const std::vector<Vec3>& I) {
  const int bodies = int(q.size());
  std::vector<Quaternion> q_ref = q;
  std::vector<Vec3> L_ref = L;
  const double dt = 1e-3;
  for (int s = 0; s < 2000; ++s) {
    for (int first = 0; first < bodies; first += kRotationLanes)
      rotate_freely_lanes(q.data() + first, L.data() + first, I.data() + first, dt,
                          std::min(kRotationLanes, bodies - first));
    for (int b = 0; b < bodies; ++b) rotate_freely(q_ref[b], L_ref[b], I[b], dt);
  }
  for (int b = 0; b < bodies; ++b) {
    const double dq = std::abs(q[b].w - q_ref[b].w) + std::abs(q[b].x - q_ref[b].x) + std::abs(q[b].y - q_ref[b].y) +
                      std::abs(q[b].z - q_ref[b].z);
    EXPECT_LT(dq, 1e-12) << "body " << b;
    EXPECT_LT(norm(L[b] - L_ref[b]) / norm(L_ref[b]), 1e-12) << "body " << b;
    trapdem::testing_support::report("body {}: quaternion off by {:.1e}, momentum by {:.1e}", b, dq,
                                     norm(L[b] - L_ref[b]) / norm(L_ref[b]));
  }
}

}  // namespace

TEST(FreeRotation, LanesAgreeWithOneBodyAtATime) {
  constexpr int kBodies = 7;
  std::vector<Quaternion> q(kBodies);
  std::vector<Vec3> L(kBodies), I(kBodies);
  for (int b = 0; b < kBodies; ++b) {
    I[b] = {1.0 + 0.1 * b, 2.0 - 0.05 * b, 3.0 + 0.2 * b};
    q[b] = normalised({0.9 - 0.1 * b, 0.1 * b, -0.3, 0.2 + 0.05 * b});
    L[b] = {0.7 - 0.2 * b, -1.1 + 0.3 * b, 0.9 + 0.1 * b};
  }
  L[5] = {40.0, -30.0, 20.0};  // ~0.05 rad a step at dt 1e-3: past the series
  expect_lanes_agree_with_one_at_a_time(q, L, I);
}

// The same for symmetric tops (two equal moments: dimers, about axis 0, the kind the lanes turn
// exactly) mixed with an oblate top, an asymmetric body and a fast one, each of which leaves the
// lanes for rotate_freely: a group takes one kind, and every body agrees with rotate_freely.
TEST(FreeRotation, LanesOfSymmetricTopsAgreeWithOneBodyAtATime) {
  constexpr int kBodies = 8;
  std::vector<Quaternion> q(kBodies);
  std::vector<Vec3> L(kBodies), I(kBodies);
  for (int b = 0; b < kBodies; ++b) {
    I[b] = {1.0 + 0.1 * b, 2.5 + 0.2 * b, 2.5 + 0.2 * b};  // prolate: axis 0
    q[b] = normalised({0.9 - 0.1 * b, 0.1 * b, -0.3, 0.2 + 0.05 * b});
    L[b] = {0.7 - 0.2 * b, -1.1 + 0.3 * b, 0.9 + 0.1 * b};
  }
  I[2] = {1.0, 1.0, 2.0};  // oblate: axis 2
  I[5] = {1.0, 2.0, 3.0};  // asymmetric
  L[6] = {40.0, -30.0, 20.0};  // past the series
  ASSERT_EQ(symmetry_axis(I[0]), 0);
  expect_lanes_agree_with_one_at_a_time(q, L, I);
}
