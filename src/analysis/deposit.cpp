#include "analysis/deposit.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

double sphere_volume_below(double zc, double r, double a) {
  const double h = std::clamp(a - (zc - r), 0.0, 2.0 * r);
  return std::numbers::pi * h * h * (3.0 * r - h) / 3.0;
}

namespace {

struct ContactCensus {
  std::vector<int> per_particle;
  double overlap_sum = 0.0, overlap_max = 0.0;  // overlap / (r_i + r_j)
  long contacts = 0;
};

// Contacts per particle (overlap > 0) from a hash of cells one largest diameter wide: each pair is
// found once, from its lower index.
ContactCensus contact_census(const Snapshot& s, const DepositSettings& settings, double cell) {
  const std::size_t n = s.size();
  auto key_of = [&](long ix, long iy, long iz) { return (ix * 1000003L + iy) * 1000003L + iz; };
  auto cell_of = [&](double v) { return long(std::floor(v / cell)); };
  const long ny_cells = std::max(1L, long(std::floor(settings.box_depth / cell)));
  const double cell_y = settings.periodic_depth ? settings.box_depth / double(ny_cells) : cell;
  auto cell_y_of = [&](double y) {
    const long iy = long(std::floor(y / cell_y));
    return settings.periodic_depth ? ((iy % ny_cells) + ny_cells) % ny_cells : iy;
  };
  std::unordered_map<long, std::vector<std::uint32_t>> cells;
  cells.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
    cells[key_of(cell_of(s.position[i].x), cell_y_of(s.position[i].y), cell_of(s.position[i].z))].push_back(
        std::uint32_t(i));
  ContactCensus census;
  std::vector<int>& count = census.per_particle;
  count.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 xi = s.position[i];
    const long cx = cell_of(xi.x), cy = cell_y_of(xi.y), cz = cell_of(xi.z);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          long iy = cy + dy;
          if (settings.periodic_depth) {
            if (ny_cells < 3 && dy != 0 && (ny_cells == 1 || dy == 1)) continue;  // the same cell twice
            iy = ((iy % ny_cells) + ny_cells) % ny_cells;
          }
          const auto it = cells.find(key_of(cx + dx, iy, cz + dz));
          if (it == cells.end()) continue;
          for (std::uint32_t j : it->second) {
            if (j <= i) continue;
            if (!s.body.empty() && s.body[i] == s.body[j]) continue;  // one clump's members overlap by design
            Vec3 d = xi - s.position[j];
            if (settings.periodic_depth) d.y -= settings.box_depth * std::round(d.y / settings.box_depth);
            const double reach = s.radius[i] + s.radius[j];
            if (norm2(d) < reach * reach) {
              ++count[i];
              ++count[j];
              const double overlap = (reach - std::sqrt(norm2(d))) / reach;
              census.overlap_sum += overlap;
              census.overlap_max = std::max(census.overlap_max, overlap);
              ++census.contacts;
            }
          }
        }
  }
  return census;
}

// Each particle's row among a snapshot of clumps' bodies (their grains, grain_view's rows).
std::vector<std::size_t> grain_row_of_members(const Snapshot& s) {
  std::unordered_map<std::int64_t, std::size_t> row_of;
  for (std::size_t k = 0; k < s.bodies.size(); ++k) row_of[s.bodies.id[k]] = k;
  std::vector<std::size_t> row(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    const auto it = row_of.find(s.body[i]);
    if (it == row_of.end())
      throw InputError(fmt::format("deposit: particle {} is a member of body {}, which the snapshot does not hold",
                                   s.id[i], s.body[i]));
    row[i] = it->second;
  }
  return row;
}

}  // namespace

DepositMetrics measure_deposit(const Snapshot& members, const DepositSettings& settings) {
  if (members.size() == 0) throw InputError("deposit: the snapshot holds no particles");
  if (!(settings.box_width > 0.0) || !(settings.box_depth > 0.0))
    throw InputError(fmt::format("deposit: box width and depth must be > 0 m (got {} x {})", settings.box_width,
                                 settings.box_depth));
  double r_max = 0.0, top = 0.0;  // m, of the particles (a clump's members)
  for (std::size_t i = 0; i < members.size(); ++i) {
    const Vec3 x = members.position[i];
    if (!(x.x >= 0.0 && x.x <= settings.box_width && x.y >= 0.0 && x.y <= settings.box_depth))
      throw InputError(fmt::format("deposit: particle {} at x = {} m, y = {} m lies outside the box {} x {} m",
                                   members.id[i], x.x, x.y, settings.box_width, settings.box_depth));
    r_max = std::max(r_max, members.radius[i]);
    top = std::max(top, x.z + members.radius[i]);
  }
  // Contacts between particles of different grains, found among the particles.
  const ContactCensus census = contact_census(members, settings, 2.0 * r_max);
  // Counts are the grains': spheres, or clumps by their centre of mass (grain_view), each clump
  // with its members' contacts. Volumes and weights are the members' spheres, each scaled by its
  // clump's union volume over the sum of its members' volumes (their overlaps would count twice):
  // a clump's volume and weight are exact, and lie where its members are, up to how the overlap
  // lens is spread among them.
  const bool clumps = !members.bodies.empty();
  const Snapshot grain_storage = clumps ? grain_view(members) : Snapshot{};
  const Snapshot& s = clumps ? grain_storage : members;
  const std::size_t n = s.size();
  std::vector<int> contacts = census.per_particle;  // per grain
  std::vector<double> volume_scale(members.size(), 1.0);
  if (clumps) {
    const std::vector<std::size_t> row = grain_row_of_members(members);
    contacts.assign(n, 0);
    std::vector<double> member_volume(n, 0.0);  // per grain: the sum of its members' spheres
    for (std::size_t i = 0; i < members.size(); ++i) {
      contacts[row[i]] += census.per_particle[i];
      member_volume[row[i]] += 4.0 / 3.0 * std::numbers::pi * std::pow(members.radius[i], 3);
    }
    for (std::size_t i = 0; i < members.size(); ++i)
      volume_scale[i] = 4.0 / 3.0 * std::numbers::pi * std::pow(s.radius[row[i]], 3) / member_volume[row[i]];
  }
  DepositMetrics m;
  m.particles = int(n);
  double d_sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) d_sum += 2.0 * s.radius[i];
  const double d = d_sum / double(n);
  m.mean_diameter = d;

  // The surface: the highest top in each column two mean diameters wide (Cartesian x), averaged.
  const int columns = std::max(1, int(settings.box_width / (2.0 * d)));
  std::vector<double> column_top(std::size_t(columns), -1.0);
  for (std::size_t i = 0; i < members.size(); ++i) {  // the particles' tops: the surface as it is
    const Vec3& x = members.position[i];
    const int c = std::min(columns - 1, int(x.x / settings.box_width * columns));
    column_top[std::size_t(c)] = std::max(column_top[std::size_t(c)], x.z + members.radius[i]);
  }
  double sum = 0.0;
  int filled = 0;
  for (double t : column_top)
    if (t >= 0.0) {
      sum += t;
      ++filled;
    }
  m.surface_height = sum / filled;
  double spread = 0.0;  // two passes: the variance without cancellation
  for (double t : column_top)
    if (t >= 0.0) spread += (t - m.surface_height) * (t - m.surface_height);
  m.surface_roughness = std::sqrt(spread / filled);

  m.contacts = census.contacts;
  m.mean_overlap = census.contacts > 0 ? census.overlap_sum / double(census.contacts) : 0.0;
  m.max_overlap = census.overlap_max;
  const double area = settings.box_width * settings.box_depth;  // m^2

  // Solid volume and contacts of the particles whose centre lies in [a, b).
  auto layer = [&](double a, double b, DepositBin& bin, double* rattlers) {
    double volume = 0.0;
    long contact_sum = 0;
    int in_layer = 0, loose = 0;
    for (std::size_t i = 0; i < members.size(); ++i) {
      const double zc = members.position[i].z, r = members.radius[i];
      if (zc + r > a && zc - r < b)
        volume += volume_scale[i] * (sphere_volume_below(zc, r, b) - sphere_volume_below(zc, r, a));
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double zc = s.position[i].z;
      if (zc >= a && zc < b) {
        ++in_layer;
        contact_sum += contacts[i];
        loose += contacts[i] < 2 ? 1 : 0;
      }
    }
    bin.z_low = a;
    bin.z_high = b;
    bin.solid_fraction = volume / (area * (b - a));
    bin.particles = in_layer;
    bin.coordination = in_layer > 0 ? double(contact_sum) / in_layer : 0.0;
    if (rattlers) *rattlers = in_layer > 0 ? double(loose) / in_layer : 0.0;
  };

  // The weight above the plane z = a per plan area: each sphere's part above it (a member's
  // scaled as its volume is), at its centre's acceleration (the acceleration varies over a
  // diameter by d/R of itself, < 1e-3 in a centrifuge).
  const bool stress = settings.solid_density > 0.0 && static_cast<bool>(settings.downward_acceleration);
  std::vector<double> weight_factor;  // rho a_down(x_i) x the volume scale, N/m^3
  if (stress) {
    weight_factor.resize(members.size());
    for (std::size_t i = 0; i < members.size(); ++i)
      weight_factor[i] = volume_scale[i] * settings.solid_density * settings.downward_acceleration(members.position[i]);
  }
  auto geostatic_stress_at = [&](double a) {
    double weight = 0.0;  // N
    for (std::size_t i = 0; i < members.size(); ++i) {
      const double zc = members.position[i].z, r = members.radius[i];
      if (zc + r <= a) continue;
      const double whole = 4.0 / 3.0 * std::numbers::pi * r * r * r;
      weight += weight_factor[i] * (whole - sphere_volume_below(zc, r, a));
    }
    return weight / area;
  };

  const double bin = settings.bin_height > 0.0 ? settings.bin_height : 5.0 * d;
  for (double a = 0.0; a < top; a += bin) {
    DepositBin b;
    layer(a, a + bin, b, nullptr);
    if (stress) b.geostatic_stress = geostatic_stress_at(a);
    m.profile.push_back(b);
  }
  if (stress) m.base_geostatic_stress = geostatic_stress_at(0.0);
  m.bulk_z_low = settings.base_margin * d;
  m.bulk_z_high = m.surface_height - settings.surface_margin * d;
  if (m.bulk_z_high > m.bulk_z_low) {
    DepositBin b;
    layer(m.bulk_z_low, m.bulk_z_high, b, &m.bulk_rattler_fraction);
    m.bulk_solid_fraction = b.solid_fraction;
    m.bulk_coordination = b.coordination;
  }
  return m;
}

}  // namespace trapdem
