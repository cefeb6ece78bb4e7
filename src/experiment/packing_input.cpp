#include "experiment/packing_input.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <unordered_map>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/cell_grid.hpp"
#include "dem/domain.hpp"
#include "io/lammps_data.hpp"
#include "io/lammps_dump.hpp"
#include "io/snapshot.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

// Adds a particle, taking its density from the file; a non-positive radius or density is kept
// as it is (the mass then is not a mass) so that packing_violations names it with its line.
void add_particle(PackingParticles& out, std::int64_t id, const Vec3& x, double radius, double density, const Vec3& v,
                  const Vec3& w, std::string origin) {
  out.particles.add(id, x, radius, density, v, w);
  out.origin.push_back(std::move(origin));
}

PackingParticles from_lammps_data(const PackingConfig& c) {
  const LammpsData data = read_lammps_data(c.from);
  const Particles& p = data.particles;
  PackingParticles out;
  out.particles.reserve(p.size());
  for (std::size_t i = 0; i < p.size(); ++i)
    add_particle(out, p.id[i], p.position[i] + c.shift, p.radius[i], p.density(i), p.velocity[i],
                 p.angular_velocity[i], fmt::format("{}:{}", c.from, data.line[i]));
  return out;
}

PackingParticles from_dump(const PackingConfig& c, double default_density) {
  const DumpAtoms dump = read_dump_atoms(c.from);
  const Snapshot& s = dump.snapshot;
  PackingParticles out;
  out.particles.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i)
    add_particle(out, s.id[i], s.position[i] + c.shift, s.radius[i], dump.density.empty() ? default_density : dump.density[i],
                 s.velocity[i], s.angular_velocity[i], fmt::format("{}:{}", c.from, dump.line[i]));
  return out;
}

// Each body of a snapshot of clumps rebuilt from `shape` (read_packing_file explains). A member
// of the snapshot is where the shape puts one when its offset from the centre of mass, turned into
// the body frame, and its radius are the shape's to 1e-6 of the grain's diameter: the snapshot's
// values are the engine's own placement (x = X + R c, rounding ~1e-16 m), so only another shape
// or size misses by that much.
void add_clumps(PackingParticles& out, const Snapshot& s, const std::string& where, const PackingConfig& c,
                const ParticleShape& shape, double density) {
  std::unordered_map<std::int64_t, std::vector<std::size_t>> rows_of;  // body id -> its member rows
  for (std::size_t i = 0; i < s.size(); ++i) rows_of[s.body[i]].push_back(i);
  std::int64_t next_member_id = 1;
  for (std::size_t k = 0; k < s.bodies.size(); ++k) {
    const std::int64_t body_id = s.bodies.id[k];
    const double diameter = 2.0 * s.bodies.radius[k];
    const ClumpTemplate grain = shape.clump->scaled_to(diameter);
    const auto found = rows_of.find(body_id);
    const std::size_t members = found == rows_of.end() ? 0 : found->second.size();
    const std::string body = fmt::format("{}, body {} (volume-equivalent diameter {:.6g} m)", where, body_id, diameter);
    if (members != grain.members.size())
      throw InputError(fmt::format("{}: {} member spheres, where [particles.shape] ({}) has {}: the packing's clumps must "
                                   "be of the configuration's shape",
                                   body, members, shape.describe(), grain.members.size()));
    const Quaternion& q = s.bodies.orientation[k];
    const double tolerance = 1e-6 * diameter;
    std::vector<char> matched(grain.members.size(), 0);
    for (std::size_t i : found->second) {
      const Vec3 offset = rotate_inverse(q, s.position[i] - s.bodies.position[k]);
      bool placed = false;
      for (std::size_t m = 0; m < grain.members.size() && !placed; ++m) {
        if (matched[m] || norm(offset - grain.members[m].centre) > tolerance ||
            std::fabs(s.radius[i] - grain.members[m].radius) > tolerance)
          continue;
        matched[m] = 1;
        placed = true;
      }
      if (!placed)
        throw InputError(fmt::format("{}: its member sphere {} (row {}, radius {:.6g} m) is at ({:.6g}, {:.6g}, {:.6g}) m "
                                     "in the body frame, where [particles.shape] ({}) has no member: the packing's "
                                     "clumps must be of the configuration's shape",
                                     body, s.id[i], i, s.radius[i], offset.x, offset.y, offset.z, shape.describe()));
    }
    const std::size_t first = out.particles.size();
    add_rigid_body(out.bodies, out.particles, body_id, next_member_id, grain, density, s.bodies.position[k] + c.shift,
                   q, s.bodies.velocity[k], s.bodies.angular_velocity[k]);
    next_member_id += std::int64_t(grain.members.size());
    for (std::size_t i = first; i < out.particles.size(); ++i)
      out.origin.push_back(fmt::format("{}, body {} member {}", where, body_id, i - first));
  }
}

// `from` is a snapshots.h5 or the run folder holding one.
PackingParticles from_snapshot(const PackingConfig& c, double default_density, const ParticleShape& shape) {
  fs::path h5 = c.from;
  if (fs::is_directory(h5)) h5 /= "snapshots.h5";
  if (!fs::exists(h5))
    throw InputError(fmt::format("{}: not found; packing.from with format = \"trapdem\" names a run folder or its "
                                 "snapshots.h5", h5.string()));
  const std::vector<SnapshotInfo> list = list_snapshots(h5);
  if (list.empty()) throw InputError(fmt::format("{}: holds no snapshot; expected at least one", h5.string()));
  const std::int64_t n = std::int64_t(list.size());
  if (c.snapshot >= n)
    throw InputError(fmt::format("{}: packing.snapshot = {}, but the file holds {} snapshot(s); expected 0 to {} "
                                 "(or no packing.snapshot: the last)", h5.string(), c.snapshot, n, n - 1));
  const SnapshotInfo& info = list[std::size_t(c.snapshot < 0 ? n - 1 : c.snapshot)];
  const Snapshot s = read_snapshot(h5, info.name);
  const std::string where = fmt::format("{} snapshot {}", h5.string(), info.name);
  if (!s.bodies.empty() && !shape.is_clump())
    throw InputError(fmt::format("{}: a snapshot of {} clumps, and [particles.shape] is spheres: set [particles.shape] "
                                 "to the clumps' shape (docs/config.md), from which each clump is rebuilt",
                                 where, s.bodies.size()));
  if (s.bodies.empty() && shape.is_clump())
    throw InputError(fmt::format("{}: a snapshot of spheres, and [particles.shape] is {}: a packing of clumps is a "
                                 "trapdem snapshot of clumps of that shape (or pour the clumps: no [packing])",
                                 where, shape.describe()));
  PackingParticles out;
  out.particles.reserve(s.size());
  if (shape.is_clump()) {
    add_clumps(out, s, where, c, shape, default_density);
    return out;
  }
  for (std::size_t i = 0; i < s.size(); ++i)
    add_particle(out, s.id[i], s.position[i] + c.shift, s.radius[i], default_density, s.velocity[i],
                 s.angular_velocity[i], fmt::format("{}, row {}", where, i));
  return out;
}

std::string describe(const PackingParticles& p, std::size_t i) {
  const Vec3& x = p.particles.position[i];
  return fmt::format("{}: particle {} at ({:.6g}, {:.6g}, {:.6g}) m, radius {:.6g} m", p.origin[i], p.particles.id[i],
                     x.x, x.y, x.z, p.particles.radius[i]);
}

// The box's faces a particle crosses by more than `allowed` (m) of its radius.
std::string outside_box(const Vec3& x, double r, const BoxConfig& box, double fraction) {
  const double allowed = fraction * r;
  std::string what;
  auto add = [&](const std::string& s) { what += (what.empty() ? "" : "; ") + s; };
  if (x.z - r < -allowed) add(fmt::format("below the base (z - r = {:.6g} m < 0)", x.z - r));
  if (x.z + r > box.height + allowed) add(fmt::format("above the box (z + r = {:.6g} m > box.height = {} m)", x.z + r, box.height));
  if (x.x - r < -allowed) add(fmt::format("through the left wall (x - r = {:.6g} m < 0)", x.x - r));
  if (x.x + r > box.width + allowed) add(fmt::format("through the right wall (x + r = {:.6g} m > box.width = {} m)", x.x + r, box.width));
  if (box.periodic_depth) {
    if (!(x.y >= 0.0 && x.y < box.depth)) add(fmt::format("outside the periodic depth (y = {:.6g} m, expected 0 <= y < {} m)", x.y, box.depth));
  } else {
    if (x.y - r < -allowed) add(fmt::format("through the back plate (y - r = {:.6g} m < 0)", x.y - r));
    if (x.y + r > box.depth + allowed) add(fmt::format("through the front window (y + r = {:.6g} m > box.depth = {} m)", x.y + r, box.depth));
  }
  return what;
}

}  // namespace

PackingParticles read_packing_file(const PackingConfig& c, double default_density, const ParticleShape& shape) {
  // A device or a pipe (/dev/zero, a FIFO) would be read without end: only files (and, for a
  // trapdem run, its folder) are packings.
  std::error_code ec;
  const fs::file_status status = fs::status(c.from, ec);
  if (fs::exists(status) && !fs::is_regular_file(status) && !(c.format == "trapdem" && fs::is_directory(status)))
    throw InputError(fmt::format("packing.from = \"{}\": not a regular file; expected a {} file", c.from,
                                 c.format == "trapdem" ? "snapshots.h5 (or a run folder)" : c.format));
  if (shape.is_clump() && c.format != "trapdem")
    throw InputError(fmt::format("packing.format = \"{}\" with [particles.shape] {}: a packing of clumps is a trapdem "
                                 "snapshot of clumps of that shape (format = \"trapdem\"); a {} file holds spheres",
                                 c.format, shape.describe(), c.format));
  if (c.format == "lammps-data") return from_lammps_data(c);
  if (c.format == "lammps-dump") return from_dump(c, default_density);
  if (c.format == "trapdem") return from_snapshot(c, default_density, shape);
  throw InputError(fmt::format("packing.format = \"{}\": expected \"lammps-data\", \"lammps-dump\" or \"trapdem\"", c.format));
}

std::vector<std::string> packing_violations(const PackingParticles& packing, const BoxConfig& box,
                                            double max_overlap_fraction, std::size_t max_lines) {
  const Particles& p = packing.particles;
  std::vector<std::string> lines;
  std::size_t more = 0;
  auto report = [&](std::string line) {
    if (lines.size() < max_lines) lines.push_back(std::move(line));
    else ++more;
  };
  std::unordered_map<std::int64_t, std::size_t> first_of;
  double r_max = 0.0;
  std::vector<char> usable(p.size(), 0);  // a positive finite radius: taken into the overlap search
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double r = p.radius[i];
    if (!(r > 0.0) || !std::isfinite(r)) {
      report(fmt::format("{}: the radius must be positive", describe(packing, i)));
      continue;
    }
    const double density = p.density(i);
    if (!(density > 0.0) || !std::isfinite(density))
      report(fmt::format("{}: density {:.6g} kg/m^3; expected a positive density", describe(packing, i), density));
    if (auto [it, fresh] = first_of.emplace(p.id[i], i); !fresh)
      report(fmt::format("{}: the id appears twice (first at {}); expected unique ids", describe(packing, i),
                         packing.origin[it->second]));
    const std::string outside = outside_box(p.position[i], r, box, max_overlap_fraction);
    if (!outside.empty())
      report(fmt::format("{}: {}; expected every particle inside the box and above the base (a wall overlap up to "
                         "numerics.max_overlap_fraction = {} of the radius is allowed)",
                         describe(packing, i), outside, max_overlap_fraction));
    usable[i] = 1;
    r_max = std::max(r_max, r);
  }

  const std::vector<std::uint32_t>& body_of = packing.bodies.body_of_particle;  // empty: spheres
  // Pairs: a cell grid of cells at least 2 r_max wide, particles counted into cells.
  Domain domain;
  domain.lower = {0.0, 0.0, 0.0};
  domain.upper = {box.width, box.depth, box.height};
  domain.periodic[1] = box.periodic_depth;
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> index;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (!usable[i]) continue;
    const Vec3& x = p.position[i];
    if (box.periodic_depth && !(x.y >= 0.0 && x.y < box.depth)) continue;  // reported above
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z)) continue;
    positions.push_back(x);
    index.push_back(static_cast<std::uint32_t>(i));
  }
  if (!positions.empty()) {
    const CellGrid grid = CellGrid::covering(positions, domain, 2.0 * r_max, 4 * positions.size() + 64);
    std::vector<std::uint32_t> cell_of(positions.size()), start(grid.total() + 1, 0), order(positions.size());
    for (std::size_t k = 0; k < positions.size(); ++k) ++start[(cell_of[k] = grid.index(positions[k])) + 1];
    for (std::size_t c = 0; c < grid.total(); ++c) start[c + 1] += start[c];
    std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
    for (std::size_t k = 0; k < positions.size(); ++k) order[fill[cell_of[k]]++] = static_cast<std::uint32_t>(k);
    std::array<std::uint32_t, 27> near{};
    for (std::size_t a = 0; a < positions.size(); ++a) {
      const int n = grid.neighbours(cell_of[a], near);
      for (int q = 0; q < n; ++q) {
        for (std::uint32_t s = start[near[q]]; s < start[near[q] + 1]; ++s) {
          const std::uint32_t b = order[s];
          if (b <= a) continue;
          const std::size_t i = index[a], j = index[b];
          if (!body_of.empty() && body_of[i] == body_of[j]) continue;  // one clump's members overlap by design
          const Vec3 d = domain.minimum_image(p.position[j] - p.position[i]);
          const double overlap = p.radius[i] + p.radius[j] - std::sqrt(dot(d, d));
          const double smaller = std::min(p.radius[i], p.radius[j]);
          if (overlap > max_overlap_fraction * smaller)
            report(fmt::format("{}: overlaps particle {} ({}) by {:.4g} m = {:.3g} of the smaller radius; expected at "
                               "most numerics.max_overlap_fraction = {}",
                               describe(packing, i), p.id[j], packing.origin[j], overlap, overlap / smaller,
                               max_overlap_fraction));
        }
      }
    }
  }
  if (more > 0) lines.push_back(fmt::format("... and {} more", more));
  return lines;
}

PackingParticles read_packing(const PackingConfig& c, const BoxConfig& box, double default_density,
                              double max_overlap_fraction, const ParticleShape& shape) {
  PackingParticles packing = read_packing_file(c, default_density, shape);
  if (packing.particles.empty())
    throw InputError(fmt::format("{}: the packing holds no particle; expected at least one", c.from));
  const std::vector<std::string> violations = packing_violations(packing, box, max_overlap_fraction);
  if (!violations.empty()) {
    std::string text;
    for (const std::string& v : violations) text += "\n  " + v;
    throw InputError(fmt::format("packing.from = \"{}\" (shift [{}, {}, {}] m): {} violation(s) of what a run's initial "
                                 "particles must keep:{}",
                                 c.from, c.shift.x, c.shift.y, c.shift.z, violations.back().rfind("... and", 0) == 0
                                     ? fmt::format("more than {}", violations.size() - 1)
                                     : fmt::to_string(violations.size()),
                                 text));
  }
  return packing;
}

}  // namespace trapdem
