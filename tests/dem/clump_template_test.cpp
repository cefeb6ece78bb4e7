// A clump's mass properties from the union of its spheres (src/dem/rigid/clump_template.hpp, issue
// 39), against exact results: a sphere; a dimer, whose union is a solid of revolution (its volume by
// the lens formula, its axial moment by a one-dimensional integral); the built-in shapes' symmetry;
// scaling; and each bad template refused with its source and sphere or line.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <string>

#include "../io/io_test_support.hpp"
#include "core/errors.hpp"
#include "dem/rigid/clump_shapes.hpp"
#include "dem/rigid/clump_template.hpp"

using namespace trapdem;
using std::numbers::pi;

namespace {

// The midpoint rule with h = r_min / 40 (the default): the volume within 0.1 %, moments within
// 0.2 % (the surface cuts the cubes at random; measured errors are about a quarter of these).
constexpr double kVolumeTolerance = 1e-3, kMomentTolerance = 2e-3;

std::string error_of(const std::vector<ClumpMember>& members) {
  try {
    make_clump_template(members, "shape.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST(ClumpTemplate, OneSphereIsTheSphere) {
  const ClumpTemplate t = make_clump_template({{{0.3, -0.2, 0.1}, 1.0}}, "sphere");
  const double volume = 4.0 / 3.0 * pi;
  EXPECT_NEAR(t.volume / volume, 1.0, kVolumeTolerance);
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(t.principal_inertia[a] / (0.4 * volume), 1.0, kMomentTolerance);
  EXPECT_NEAR(norm(t.members[0].centre), 0.0, 1e-3);  // centred on the centre of mass
  EXPECT_NEAR(t.volume_equivalent_diameter(), 2.0, 1e-3);
}

// Two unit spheres d = 1 apart: V = 2 (4/3 pi) - lens, lens = pi (4 r + d) (2 r - d)^2 / 12; the
// axial moment integral of pi rho(x)^4 / 2 over the axis, rho the union's radius at x (the nearer
// sphere's), the transverse moments from the second moment about the centre.
TEST(ClumpTemplate, DimerAgainstTheSolidOfRevolution) {
  const double r = 1.0, d = 1.0;
  const ClumpTemplate t = make_clump_template({{{0.0, 0.0, 0.0}, r}, {{d, 0.0, 0.0}, r}}, "dimer");
  const double lens = pi * (4.0 * r + d) * (2.0 * r - d) * (2.0 * r - d) / 12.0;
  const double volume = 2.0 * 4.0 / 3.0 * pi * r * r * r - lens;
  EXPECT_NEAR(t.volume / volume, 1.0, kVolumeTolerance);
  // Simpson's rule on the profile, 20000 intervals: exact to 1e-9 here.
  const double a = -r - 0.5 * d, b = r + 0.5 * d;  // about the centre of mass at d / 2
  const int n = 20000;
  double axial = 0.0, second = 0.0, check_volume = 0.0;
  for (int k = 0; k <= n; ++k) {
    const double x = a + (b - a) * k / n;
    const double nearest = std::min(std::abs(x + 0.5 * d), std::abs(x - 0.5 * d));
    const double rho2 = std::max(0.0, r * r - nearest * nearest);
    const double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
    axial += w * pi * rho2 * rho2 / 2.0;
    second += w * pi * rho2 * x * x;  // integral of x^2 dV
    check_volume += w * pi * rho2;
  }
  const double step = (b - a) / n / 3.0;
  axial *= step;
  second *= step;
  check_volume *= step;
  ASSERT_NEAR(check_volume / volume, 1.0, 1e-9);
  const double transverse = second + axial / 2.0;  // integral of (x^2 + z^2) dV, z^2 = half of rho^2's moment
  EXPECT_NEAR(t.principal_inertia.x / axial, 1.0, kMomentTolerance);  // the smallest: about the axis
  EXPECT_NEAR(t.principal_inertia.y / transverse, 1.0, kMomentTolerance);
  EXPECT_NEAR(t.principal_inertia.z / transverse, 1.0, kMomentTolerance);
  // The axis is the principal x axis; the members at -d/2 and +d/2 along it.
  EXPECT_NEAR(std::abs(t.reference_axes_x.x), 1.0, 1e-9);
  EXPECT_NEAR(std::abs(t.members[0].centre.x), 0.5 * d, 1e-3);
  EXPECT_NEAR(t.members[0].centre.x + t.members[1].centre.x, 0.0, 1e-3);
  // Not the sum of the spheres: that would be 18.5 % more volume here.
  EXPECT_NEAR(2.0 * 4.0 / 3.0 * pi / t.volume, 1.185, 0.002);
}

// The same shape turned and moved: the same volume and moments (to the rule's tolerance).
TEST(ClumpTemplate, FrameIndependent) {
  const ClumpTemplate a = make_clump_template(dimer_members(1.5), "dimer");
  std::vector<ClumpMember> turned;
  for (const ClumpMember& m : dimer_members(1.5)) {
    const Vec3 c = m.centre;  // 30 degrees about z, then 40 about x, then moved
    const double c1 = std::cos(pi / 6), s1 = std::sin(pi / 6), c2 = std::cos(2 * pi / 9), s2 = std::sin(2 * pi / 9);
    const Vec3 p{c1 * c.x - s1 * c.y, s1 * c.x + c1 * c.y, c.z};
    turned.push_back({{p.x + 3.0, c2 * p.y - s2 * p.z - 1.0, s2 * p.y + c2 * p.z + 0.5}, m.radius});
  }
  const ClumpTemplate b = make_clump_template(turned, "turned dimer");
  EXPECT_NEAR(b.volume / a.volume, 1.0, kVolumeTolerance);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(b.principal_inertia[k] / a.principal_inertia[k], 1.0, kMomentTolerance);
}

TEST(ClumpTemplate, BuiltInShapes) {
  // Tetrahedral: cubic symmetry, three equal moments.
  const ClumpTemplate tetra = make_clump_template(tetrahedral_members(1.0), "tetrahedral");
  EXPECT_NEAR(tetra.principal_inertia.x / tetra.principal_inertia.z, 1.0, kMomentTolerance);
  // A dimer's aspect: the length along the axis over the width.
  const ClumpTemplate dimer = make_clump_template(dimer_members(1.6), "dimer");
  const double length = 2.0 * std::abs(dimer.members[0].centre.x) + 2.0;
  EXPECT_NEAR(length / 2.0, 1.6, 1e-3);
  // Sub-angular: one connected body, the same for the same parameters, elongated along x when asked.
  const auto grain = sub_angular_members(8, 0.6, 1.4, 0.8);
  EXPECT_EQ(grain.size(), 9u);
  const ClumpTemplate g = make_clump_template(grain, "sub-angular");
  EXPECT_EQ(make_clump_template(sub_angular_members(8, 0.6, 1.4, 0.8), "again").volume, g.volume);
  EXPECT_LT(g.principal_inertia.x, g.principal_inertia.z);
  EXPECT_THROW(dimer_members(2.0), InputError);
  EXPECT_THROW(tetrahedral_members(0.0), InputError);
  EXPECT_THROW(sub_angular_members(1, 0.5), InputError);
  EXPECT_THROW(sub_angular_members(6, 1.5), InputError);
}

TEST(ClumpTemplate, ScaledToAVolumeEquivalentDiameter) {
  const ClumpTemplate t = make_clump_template(dimer_members(1.5), "dimer");
  const ClumpTemplate s = t.scaled_to(0.002);  // 2 mm
  EXPECT_NEAR(s.volume_equivalent_diameter(), 0.002, 1e-15);
  const double k = 0.002 / t.volume_equivalent_diameter();
  EXPECT_NEAR(s.principal_inertia.x / t.principal_inertia.x, std::pow(k, 5), 1e-12 * std::pow(k, 5));
  EXPECT_NEAR(s.members[1].radius, k * t.members[1].radius, 1e-18);
}

TEST(ClumpTemplate, BadTemplatesNamed) {
  EXPECT_EQ(error_of({}), "shape.txt: a clump needs at least one sphere");
  EXPECT_NE(error_of({{{0, 0, 0}, 1.0}, {{0.5, 0, 0}, -1.0}}).find("shape.txt: sphere 2: radius -1 m"), std::string::npos);
  const std::string apart = error_of({{{0, 0, 0}, 1.0}, {{1.5, 0, 0}, 1.0}, {{5.0, 0, 0}, 1.0}});
  EXPECT_NE(apart.find("shape.txt: sphere 3 does not overlap the others"), std::string::npos) << apart;
  // Just touching is not overlapping.
  EXPECT_NE(error_of({{{0, 0, 0}, 1.0}, {{2.0, 0, 0}, 1.0}}).find("sphere 2 does not overlap"), std::string::npos);
}

TEST(ClumpTemplate, TemplateFileReadOrRefusedWithItsLine) {
  const io_testing::ScratchDir scratch("trapdem-clump-file");
  const auto file = scratch / "grain.txt";
  std::ofstream(file) << "# a dimer\n0 0 0 1.0\n\n1.0 0 0 1.0  # second\n";
  const auto members = read_clump_members(file);
  ASSERT_EQ(members.size(), 2u);
  EXPECT_EQ(members[1].centre.x, 1.0);
  const auto error_in = [&](const std::string& text) {
    std::ofstream(file) << text;
    try {
      read_clump_members(file);
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(error_in("0 0 0 1\n0 0 1\n"), file.string() + ":2: 3 numbers; expected four, \"x y z radius\"");
  EXPECT_EQ(error_in("0 0 0 1\n0 0 x 1\n"), file.string() + ":2: 'x' is not a finite number; expected \"x y z radius\"");
  EXPECT_EQ(error_in("0 0 0 0\n"), file.string() + ":1: radius 0; expected a positive number");
  EXPECT_EQ(error_in("# nothing\n\n"), file.string() + ": no sphere in the clump template (lines \"x y z radius\")");
  EXPECT_THROW(read_clump_members(scratch / "missing.txt"), InputError);
}
