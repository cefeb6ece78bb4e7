#include "dem/rigid/clump_template.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

using Matrix3 = std::array<std::array<double, 3>, 3>;

// Eigenvalues (ascending) and unit eigenvectors (columns) of a symmetric 3x3 matrix by cyclic
// Jacobi rotations (Golub & Van Loan, Matrix Computations, sec. 8.5): exact to round-off in a few
// sweeps for 3x3.
void symmetric_eigen(Matrix3 a, Vec3& values, Matrix3& vectors) {
  vectors = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  for (int sweep = 0; sweep < 50; ++sweep) {
    const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
    const double scale = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
    if (off <= 1e-30 * scale) break;
    for (int p = 0; p < 2; ++p)
      for (int q = p + 1; q < 3; ++q) {
        if (a[p][q] == 0.0) continue;
        const double theta = (a[q][q] - a[p][p]) / (2.0 * a[p][q]);
        const double t = (theta >= 0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
        const double c = 1.0 / std::sqrt(t * t + 1.0), s = t * c;
        for (int k = 0; k < 3; ++k) {  // A <- J^T A J
          const double akp = a[k][p], akq = a[k][q];
          a[k][p] = c * akp - s * akq;
          a[k][q] = s * akp + c * akq;
        }
        for (int k = 0; k < 3; ++k) {
          const double apk = a[p][k], aqk = a[q][k];
          a[p][k] = c * apk - s * aqk;
          a[q][k] = s * apk + c * aqk;
        }
        for (int k = 0; k < 3; ++k) {
          const double vkp = vectors[k][p], vkq = vectors[k][q];
          vectors[k][p] = c * vkp - s * vkq;
          vectors[k][q] = s * vkp + c * vkq;
        }
      }
  }
  std::array<int, 3> order{0, 1, 2};
  std::sort(order.begin(), order.end(), [&](int i, int j) { return a[i][i] < a[j][j]; });
  Matrix3 sorted{};
  for (int c = 0; c < 3; ++c) {
    values[c] = a[order[std::size_t(c)]][order[std::size_t(c)]];
    for (int r = 0; r < 3; ++r) sorted[std::size_t(r)][std::size_t(c)] = vectors[std::size_t(r)][std::size_t(order[std::size_t(c)])];
  }
  vectors = sorted;
  // A right-handed frame: the third axis the cross product of the first two.
  const Vec3 e0{vectors[0][0], vectors[1][0], vectors[2][0]}, e1{vectors[0][1], vectors[1][1], vectors[2][1]};
  const Vec3 e2 = cross(e0, e1);
  for (int r = 0; r < 3; ++r) vectors[std::size_t(r)][2] = e2[r];
}

void check_members(const std::vector<ClumpMember>& members, const std::string& source) {
  if (members.empty()) throw InputError(fmt::format("{}: a clump needs at least one sphere", source));
  for (std::size_t i = 0; i < members.size(); ++i) {
    const ClumpMember& m = members[i];
    if (!(m.radius > 0.0) || !std::isfinite(m.radius))
      throw InputError(fmt::format("{}: sphere {}: radius {} m; expected a positive number", source, i + 1, m.radius));
    if (!is_finite(m.centre))
      throw InputError(fmt::format("{}: sphere {}: its centre is not a finite position", source, i + 1));
  }
  // Connected: every member reached from the first through overlapping members.
  std::vector<char> reached(members.size(), 0);
  std::vector<std::size_t> stack{0};
  reached[0] = 1;
  while (!stack.empty()) {
    const std::size_t i = stack.back();
    stack.pop_back();
    for (std::size_t j = 0; j < members.size(); ++j) {
      if (reached[j]) continue;
      const double reach = members[i].radius + members[j].radius;
      if (norm2(members[i].centre - members[j].centre) < reach * reach) {
        reached[j] = 1;
        stack.push_back(j);
      }
    }
  }
  for (std::size_t j = 0; j < members.size(); ++j)
    if (!reached[j])
      throw InputError(fmt::format("{}: sphere {} does not overlap the others (a clump must be one connected body: "
                                   "each sphere overlapping at least one other, centres closer than the sum of the radii)",
                                   source, j + 1));
}

}  // namespace

double ClumpTemplate::volume_equivalent_diameter() const { return std::cbrt(6.0 * volume / std::numbers::pi); }

double ClumpTemplate::bounding_radius() const {
  double reach = 0.0;
  for (const ClumpMember& m : members) reach = std::max(reach, norm(m.centre) + m.radius);
  return reach;
}

double ClumpTemplate::smallest_radius() const {
  double r = std::numeric_limits<double>::infinity();
  for (const ClumpMember& m : members) r = std::min(r, m.radius);
  return r;
}

ClumpTemplate ClumpTemplate::scaled_to(double diameter) const {
  const double s = diameter / volume_equivalent_diameter();
  ClumpTemplate t = *this;
  for (ClumpMember& m : t.members) {
    m.centre *= s;
    m.radius *= s;
  }
  t.volume *= s * s * s;
  t.principal_inertia *= s * s * s * s * s;
  return t;
}

namespace {

// Moments (ascending) that differ by round-off only are made equal bit for bit: a shape symmetric
// about an axis (a dimer; the grid treats the two transverse axes alike) is then a symmetric top,
// whose free rotation is integrated exactly (free_rotation.hpp). 1e-9 of the largest moment is far
// above the sums' round-off (~1e-15) and far below the integration's error (~1e-3): a shape whose
// moments differ by the rule's error, a regular tetrahedron's say, keeps them as computed.
void equalise_round_off(Vec3& moments) {
  const double tolerance = 1e-9 * moments.z;
  const bool low = moments.y - moments.x <= tolerance, high = moments.z - moments.y <= tolerance;
  if (low && high) {
    moments.x = moments.y = moments.z = (moments.x + moments.y + moments.z) / 3.0;
  } else if (low) {
    moments.x = moments.y = 0.5 * (moments.x + moments.y);
  } else if (high) {
    moments.y = moments.z = 0.5 * (moments.y + moments.z);
  }
}

}  // namespace

ClumpTemplate make_clump_template(const std::vector<ClumpMember>& members, const std::string& source,
                                  int cells_per_min_radius) {
  check_members(members, source);
  if (cells_per_min_radius < 2) throw InputError("make_clump_template: at least 2 cells per radius");
  Vec3 lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  double r_min = 1e300;
  for (const ClumpMember& m : members) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], m.centre[a] - m.radius);
      hi[a] = std::max(hi[a], m.centre[a] + m.radius);
    }
    r_min = std::min(r_min, m.radius);
  }
  // At most ~8 million cubes (a member far smaller than the others would ask for more): then the
  // cube grows, and the error with it.
  const double box = (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
  const double h = std::max(r_min / cells_per_min_radius, std::cbrt(box / 8.0e6));
  std::array<long, 3> n{};
  for (int a = 0; a < 3; ++a) n[std::size_t(a)] = std::max(1L, long(std::ceil((hi[a] - lo[a]) / h)));
  // Sums over the cubes whose centre lies in the union: count, first and second moments, each
  // cube of volume h^3 (the midpoint rule). Exact sums in x of one row (long double) keep the
  // round-off far below the rule's error at millions of cubes.
  long double count = 0, sx = 0, sy = 0, sz = 0, sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;
  for (long k = 0; k < n[2]; ++k) {
    const double z = lo.z + (k + 0.5) * h;
    for (long j = 0; j < n[1]; ++j) {
      const double y = lo.y + (j + 0.5) * h;
      for (long i = 0; i < n[0]; ++i) {
        const double x = lo.x + (i + 0.5) * h;
        bool inside = false;
        for (const ClumpMember& m : members) {
          const double dx = x - m.centre.x, dy = y - m.centre.y, dz = z - m.centre.z;
          if (dx * dx + dy * dy + dz * dz <= m.radius * m.radius) {
            inside = true;
            break;
          }
        }
        if (!inside) continue;
        count += 1;
        sx += x; sy += y; sz += z;
        sxx += x * x; syy += y * y; szz += z * z;
        sxy += x * y; sxz += x * z; syz += y * z;
      }
    }
  }
  const double cell = h * h * h;
  ClumpTemplate t;
  t.name = source;
  t.volume = double(count) * cell;
  const Vec3 c{double(sx / count), double(sy / count), double(sz / count)};
  // Second moments about the centre of mass, per unit density: integral of x_i x_j dV.
  const double Cxx = double(sxx) * cell - t.volume * c.x * c.x, Cyy = double(syy) * cell - t.volume * c.y * c.y,
               Czz = double(szz) * cell - t.volume * c.z * c.z;
  const double Cxy = double(sxy) * cell - t.volume * c.x * c.y, Cxz = double(sxz) * cell - t.volume * c.x * c.z,
               Cyz = double(syz) * cell - t.volume * c.y * c.z;
  // The inertia tensor per unit density: I = tr(C) 1 - C.
  const Matrix3 inertia{{{Cyy + Czz, -Cxy, -Cxz}, {-Cxy, Cxx + Czz, -Cyz}, {-Cxz, -Cyz, Cxx + Cyy}}};
  Matrix3 axes{};
  symmetric_eigen(inertia, t.principal_inertia, axes);
  equalise_round_off(t.principal_inertia);
  t.reference_axes_x = {axes[0][0], axes[1][0], axes[2][0]};
  t.reference_axes_y = {axes[0][1], axes[1][1], axes[2][1]};
  t.reference_axes_z = {axes[0][2], axes[1][2], axes[2][2]};
  for (const ClumpMember& m : members) {
    const Vec3 d = m.centre - c;
    t.members.push_back({{dot(d, t.reference_axes_x), dot(d, t.reference_axes_y), dot(d, t.reference_axes_z)}, m.radius});
  }
  return t;
}

}  // namespace trapdem
