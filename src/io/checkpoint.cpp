#include "io/checkpoint.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "io/particle_checks.hpp"

namespace trapdem {

namespace {

constexpr const char* kFormat = "trapdem-checkpoint";
constexpr std::int64_t kVersion = 1;

// ContactHistory as three columns, so that h5py users see plain arrays.
void write_history(const Hdf5Group& g, const std::vector<ContactHistory>& history) {
  std::vector<Vec3> tangential, rolling;
  std::vector<std::uint32_t> flags;
  tangential.reserve(history.size());
  rolling.reserve(history.size());
  flags.reserve(history.size());
  for (const ContactHistory& h : history) {
    tangential.push_back(h.tangential_spring);
    rolling.push_back(h.rolling_spring);
    flags.push_back(h.flags);
  }
  g.write_vec3s("tangential_spring", tangential, "m");
  g.write_vec3s("rolling_spring", rolling, "N m");
  g.write_uint32s("flags", flags);
}

std::vector<ContactHistory> read_history(const Hdf5Group& g) {
  const std::vector<Vec3> tangential = g.read_vec3s("tangential_spring");
  const std::vector<Vec3> rolling = g.read_vec3s("rolling_spring");
  const std::vector<std::uint32_t> flags = g.read_uint32s("flags");
  if (rolling.size() != tangential.size() || flags.size() != tangential.size())
    throw FileError(fmt::format("{}: history columns differ in length", g.describe()));
  std::vector<ContactHistory> history(tangential.size());
  for (std::size_t k = 0; k < history.size(); ++k) history[k] = {tangential[k], rolling[k], flags[k]};
  return history;
}

void write_particles(const Hdf5Group& g, const Particles& p) {
  g.write_int64s("id", p.id);
  g.write_doubles("radius", p.radius, "m");
  g.write_doubles("mass", p.mass, "kg");
  g.write_doubles("inv_mass", p.inv_mass, "1/kg");
  g.write_doubles("inv_inertia", p.inv_inertia, "1/(kg m^2)");
  g.write_vec3s("position", p.position, "m");
  g.write_vec3s("velocity", p.velocity, "m/s");
  g.write_vec3s("angular_velocity", p.angular_velocity, "rad/s");
  g.write_vec3s("force", p.force, "N");
  g.write_vec3s("torque", p.torque, "N m");
  g.write_int3s("image", p.image);
}

Particles read_particles(const Hdf5Group& g) {
  Particles p;
  p.id = g.read_int64s("id");
  p.radius = g.read_doubles("radius");
  p.mass = g.read_doubles("mass");
  p.inv_mass = g.read_doubles("inv_mass");
  p.inv_inertia = g.read_doubles("inv_inertia");
  p.position = g.read_vec3s("position");
  p.velocity = g.read_vec3s("velocity");
  p.angular_velocity = g.read_vec3s("angular_velocity");
  p.force = g.read_vec3s("force");
  p.torque = g.read_vec3s("torque");
  p.image = g.read_int3s("image");
  const std::size_t n = p.id.size();
  for (std::size_t size : {p.radius.size(), p.mass.size(), p.inv_mass.size(), p.inv_inertia.size(),
                           p.position.size(), p.velocity.size(), p.angular_velocity.size(), p.force.size(),
                           p.torque.size(), p.image.size()}) {
    if (size != n)
      throw FileError(fmt::format("{}: particle arrays differ in length ({} ids, an array of {})", g.describe(), n, size));
  }
  const std::string where = g.describe();
  check_particle_rows(where, p.id, p.position, p.radius, p.velocity, p.angular_velocity, /*distinct_ids=*/false);
  check_positive_column(where, "mass (kg)", p.id, p.mass);
  check_positive_column(where, "inv_mass (1/kg)", p.id, p.inv_mass);
  check_positive_column(where, "inv_inertia (1/(kg m^2))", p.id, p.inv_inertia);
  check_finite_column(where, "force (N)", p.id, p.force);
  check_finite_column(where, "torque (N m)", p.id, p.torque);
  return p;
}

void write_walls(const Hdf5Group& g, const std::vector<WallState>& walls) {
  std::vector<std::string> names;
  std::vector<Vec3> origin, displacement, force, torque, velocity;
  for (const WallState& w : walls) {
    names.push_back(w.name);
    origin.push_back(w.origin);
    displacement.push_back(w.displacement);
    force.push_back(w.force);
    torque.push_back(w.torque);
    velocity.push_back(w.current_velocity);
  }
  g.write_strings("name", names);
  g.write_vec3s("origin", origin, "m");
  g.write_vec3s("displacement", displacement, "m");
  g.write_vec3s("force", force, "N");
  g.write_vec3s("torque", torque, "N m");
  g.write_vec3s("current_velocity", velocity, "m/s");
}

std::vector<WallState> read_walls(const Hdf5Group& g) {
  const std::vector<std::string> names = g.read_strings("name");
  const std::vector<Vec3> origin = g.read_vec3s("origin"), displacement = g.read_vec3s("displacement"),
                          force = g.read_vec3s("force"), torque = g.read_vec3s("torque"),
                          velocity = g.read_vec3s("current_velocity");
  const std::size_t n = names.size();
  if (origin.size() != n || displacement.size() != n || force.size() != n || torque.size() != n ||
      velocity.size() != n)
    throw FileError(fmt::format("{}: wall arrays differ in length", g.describe()));
  std::vector<WallState> walls(n);
  for (std::size_t k = 0; k < n; ++k) walls[k] = {names[k], origin[k], displacement[k], force[k], torque[k], velocity[k]};
  return walls;
}

void write_lists(const Hdf5Group& g, const Simulation::ListState& lists) {
  const Hdf5Group pairs = g.create_group("pairs");
  pairs.write_uint32s("first", lists.pairs.first);
  pairs.write_uint32s("partner", lists.pairs.partner);
  write_history(pairs, lists.pairs.history);

  const Hdf5Group wall_list = g.create_group("wall_candidates");
  wall_list.write_uint32s("first", lists.walls.first);
  wall_list.write_uint32s("wall", lists.walls.wall);
  wall_list.write_vec3s("force", lists.walls.force, "N");
  write_history(wall_list, lists.walls.history);

  const Hdf5Group build = g.create_group("build");
  build.write_vec3s("position_at_build", lists.position_at_build, "m");
  build.write_vec3s("wall_displacement_at_build", lists.wall_displacement_at_build, "m");
  build.set_double_attribute("skin_at_build", lists.skin_at_build);  // m
}

Simulation::ListState read_lists(const Hdf5Group& g) {
  Simulation::ListState lists;
  const Hdf5Group pairs = g.group("pairs");
  lists.pairs.first = pairs.read_uint32s("first");
  lists.pairs.partner = pairs.read_uint32s("partner");
  lists.pairs.history = read_history(pairs);

  const Hdf5Group wall_list = g.group("wall_candidates");
  lists.walls.first = wall_list.read_uint32s("first");
  lists.walls.wall = wall_list.read_uint32s("wall");
  lists.walls.force = wall_list.read_vec3s("force");
  lists.walls.history = read_history(wall_list);

  const Hdf5Group build = g.group("build");
  lists.position_at_build = build.read_vec3s("position_at_build");
  lists.wall_displacement_at_build = build.read_vec3s("wall_displacement_at_build");
  // An earlier version's checkpoint has none: 0, the skin of the run that resumes it.
  if (build.has_attribute("skin_at_build")) lists.skin_at_build = build.double_attribute("skin_at_build");
  return lists;
}

// The rigid bodies' state (clumps): every per-body and per-member array of RigidBodies but the
// derived ones, which restore() finds again from the particles' order.
RigidBodies body_state(const RigidBodies& b) {
  RigidBodies s;
  s.id = b.id;
  s.mass = b.mass;
  s.volume = b.volume;
  s.principal_inertia = b.principal_inertia;
  s.position = b.position;
  s.velocity = b.velocity;
  s.orientation = b.orientation;
  s.angular_momentum = b.angular_momentum;
  s.force = b.force;
  s.torque = b.torque;
  s.first_member = b.first_member;
  s.member_id = b.member_id;
  s.member_offset = b.member_offset;
  return s;
}

void write_bodies(const Hdf5Group& g, const RigidBodies& b) {
  g.write_int64s("id", b.id);
  g.write_doubles("mass", b.mass, "kg");
  g.write_doubles("volume", b.volume, "m^3");
  g.write_vec3s("principal_inertia", b.principal_inertia, "kg m^2");
  g.write_vec3s("position", b.position, "m");
  g.write_vec3s("velocity", b.velocity, "m/s");
  g.write_quaternions("orientation", b.orientation);
  g.write_vec3s("angular_momentum", b.angular_momentum, "kg m^2/s");
  g.write_vec3s("force", b.force, "N");
  g.write_vec3s("torque", b.torque, "N m");
  g.write_uint32s("first_member", b.first_member);
  g.write_int64s("member_id", b.member_id);
  g.write_vec3s("member_offset", b.member_offset, "m");
}

// The bodies, checked as the particles are (read_particles) and against them: every particle a
// member of exactly one body (check_body_members).
RigidBodies read_bodies(const Hdf5Group& g, const std::vector<std::int64_t>& particle_id) {
  RigidBodies b;
  b.id = g.read_int64s("id");
  b.mass = g.read_doubles("mass");
  b.volume = g.read_doubles("volume");
  b.principal_inertia = g.read_vec3s("principal_inertia");
  b.position = g.read_vec3s("position");
  b.velocity = g.read_vec3s("velocity");
  b.orientation = g.read_quaternions("orientation");
  b.angular_momentum = g.read_vec3s("angular_momentum");
  b.force = g.read_vec3s("force");
  b.torque = g.read_vec3s("torque");
  b.first_member = g.read_uint32s("first_member");
  b.member_id = g.read_int64s("member_id");
  b.member_offset = g.read_vec3s("member_offset");
  const std::size_t n = b.id.size();
  for (std::size_t size : {b.mass.size(), b.volume.size(), b.principal_inertia.size(), b.position.size(), b.velocity.size(),
                           b.orientation.size(), b.angular_momentum.size(), b.force.size(), b.torque.size()}) {
    if (size != n)
      throw FileError(fmt::format("{}: body arrays differ in length ({} ids, an array of {})", g.describe(), n, size));
  }
  if (b.member_offset.size() != b.member_id.size())
    throw FileError(fmt::format("{}: member arrays differ in length ({} member ids, {} offsets)", g.describe(),
                                b.member_id.size(), b.member_offset.size()));
  const std::string where = g.describe();
  check_body_rows(where, b.id, b.position, b.velocity, b.orientation);
  check_positive_column(where, "mass (kg)", b.id, b.mass, "body");
  check_positive_column(where, "volume (m^3)", b.id, b.volume, "body");
  for (std::size_t k = 0; k < n; ++k) {
    const Vec3& inertia = b.principal_inertia[k];
    if (!(inertia.x > 0.0 && inertia.y > 0.0 && inertia.z > 0.0) || !is_finite(inertia))
      throw FileError(fmt::format("{}: row {} (body id {}): principal_inertia ({}, {}, {}) kg m^2: expected positive "
                                  "finite numbers (the file is damaged or was not written by trapdem)",
                                  where, k, b.id[k], inertia.x, inertia.y, inertia.z));
  }
  check_finite_column(where, "angular_momentum (kg m^2/s)", b.id, b.angular_momentum, "body");
  check_finite_column(where, "force (N)", b.id, b.force, "body");
  check_finite_column(where, "torque (N m)", b.id, b.torque, "body");
  check_body_members(where, b.id, b.first_member, b.member_id, particle_id);
  check_finite_column(where, "member_offset (m)", b.member_id, b.member_offset, "member");
  return b;
}

// The contact histories by particle ids (a checkpoint of a run on several ranks).
void write_histories(const Hdf5Group& g, const HistoryArchive& a) {
  std::vector<std::int64_t> low, high, particle;
  std::vector<std::uint32_t> wall;
  std::vector<ContactHistory> pair_history, wall_history;
  for (const auto& r : a.pairs) {
    low.push_back(r.low);
    high.push_back(r.high);
    pair_history.push_back(r.history);
  }
  for (const auto& r : a.walls) {
    particle.push_back(r.particle);
    wall.push_back(r.wall);
    wall_history.push_back(r.history);
  }
  const Hdf5Group pairs = g.create_group("pairs");
  pairs.write_int64s("low_id", low);
  pairs.write_int64s("high_id", high);
  write_history(pairs, pair_history);
  const Hdf5Group walls = g.create_group("walls");
  walls.write_int64s("particle_id", particle);
  walls.write_uint32s("wall", wall);
  write_history(walls, wall_history);
}

HistoryArchive read_histories(const Hdf5Group& g) {
  HistoryArchive a;
  const Hdf5Group pairs = g.group("pairs"), walls = g.group("walls");
  const std::vector<std::int64_t> low = pairs.read_int64s("low_id"), high = pairs.read_int64s("high_id");
  const std::vector<ContactHistory> pair_history = read_history(pairs);
  if (high.size() != low.size() || pair_history.size() != low.size())
    throw FileError(fmt::format("{}: pair history columns differ in length", pairs.describe()));
  for (std::size_t k = 0; k < low.size(); ++k) a.pairs.push_back({low[k], high[k], pair_history[k]});
  const std::vector<std::int64_t> particle = walls.read_int64s("particle_id");
  const std::vector<std::uint32_t> wall = walls.read_uint32s("wall");
  const std::vector<ContactHistory> wall_history = read_history(walls);
  if (wall.size() != particle.size() || wall_history.size() != particle.size())
    throw FileError(fmt::format("{}: wall history columns differ in length", walls.describe()));
  for (std::size_t k = 0; k < particle.size(); ++k) a.walls.push_back({particle[k], wall[k], wall_history[k]});
  return a;
}

}  // namespace

Checkpoint capture_checkpoint(const Simulation& simulation, std::map<std::string, std::string> metadata) {
  Checkpoint c;
  c.particles = simulation.particles();
  c.bodies = body_state(simulation.bodies());
  c.lists = simulation.list_state();
  c.time = simulation.time();
  c.time_step = simulation.time_step();
  c.stats = simulation.stats();
  for (const Wall& w : simulation.walls())
    c.walls.push_back({w.name, w.origin, w.displacement, w.force, w.torque, w.current_velocity});
  c.metadata = std::move(metadata);
  return c;
}

void write_checkpoint(const std::filesystem::path& path, const Checkpoint& c) {
  write_atomically(path, [&](const std::filesystem::path& temporary) {
    Hdf5File file = Hdf5File::create_in_memory(path);
    file.set_string_attribute("format", kFormat);
    file.set_int_attribute("version", kVersion);
    file.set_double_attribute("time", c.time);
    file.set_double_attribute("time_step", c.time_step);
    file.set_int_attribute("steps", c.stats.steps);
    file.set_int_attribute("rebuilds", c.stats.rebuilds);
    file.set_int_attribute("rebuilds_since_reorder", c.lists.rebuilds_since_reorder);

    write_particles(file.create_group("particles"), c.particles);
    if (!c.bodies.empty()) write_bodies(file.create_group("bodies"), c.bodies);  // a run of spheres has none
    write_lists(file, c.lists);
    write_walls(file.create_group("walls"), c.walls);
    if (c.histories) write_histories(file.create_group("histories_by_id"), *c.histories);
    if (!c.ranks.empty()) {
      const Hdf5Group ranks = file.create_group("ranks");
      ranks.set_int_attribute("count", std::int64_t(c.ranks.size()));
      for (std::size_t r = 0; r < c.ranks.size(); ++r) {
        const RankState& rank = c.ranks[r];
        const Hdf5Group g = ranks.create_group(std::to_string(r));
        g.set_int_attribute("ghosts", std::int64_t(rank.ghosts));
        g.set_int_attribute("rebuilds_since_reorder", rank.lists.rebuilds_since_reorder);
        write_particles(g.create_group("particles"), rank.particles);
        write_lists(g, rank.lists);
        g.write_uint8s("decomposition", rank.decomposition);
      }
    }

    const Hdf5Group metadata = file.create_group("metadata");
    for (const auto& [key, value] : c.metadata) metadata.set_string_attribute(key, value);
    file.write_image(temporary);
  });
}

Checkpoint read_checkpoint(const std::filesystem::path& path) {
  Hdf5File file = Hdf5File::open_read(path);
  if (!file.has_attribute("format") || file.string_attribute("format") != kFormat)
    throw FileError(fmt::format("{}: not a trapdem checkpoint (no format = \"{}\" attribute)", path.string(), kFormat));
  const std::int64_t version = file.int_attribute("version");
  if (version != kVersion)
    throw FileError(fmt::format("{}: checkpoint version {} is not supported (this build reads version {})",
                                path.string(), version, kVersion));
  Checkpoint c;
  c.time = file.double_attribute("time");
  c.time_step = file.double_attribute("time_step");
  c.stats.steps = file.int_attribute("steps");
  c.stats.rebuilds = file.int_attribute("rebuilds");
  c.lists.rebuilds_since_reorder = file.int_attribute("rebuilds_since_reorder");

  c.particles = read_particles(file.group("particles"));
  // No group: a run of spheres, or a file written before checkpoints held bodies.
  if (file.has("bodies")) c.bodies = read_bodies(file.group("bodies"), c.particles.id);

  const std::int64_t rebuilds_since_reorder = c.lists.rebuilds_since_reorder;
  c.lists = read_lists(file);
  c.lists.rebuilds_since_reorder = rebuilds_since_reorder;

  c.walls = read_walls(file.group("walls"));
  if (file.has("histories_by_id")) c.histories = read_histories(file.group("histories_by_id"));
  if (file.has("ranks")) {
    const Hdf5Group ranks = file.group("ranks");
    const std::int64_t count = ranks.int_attribute("count");
    for (std::int64_t r = 0; r < count; ++r) {
      const Hdf5Group g = ranks.group(std::to_string(r));
      RankState rank;
      rank.particles = read_particles(g.group("particles"));
      rank.ghosts = std::size_t(g.int_attribute("ghosts"));
      if (rank.ghosts > rank.particles.size())
        throw FileError(fmt::format("{}: {} ghosts among {} particles", g.describe(), rank.ghosts, rank.particles.size()));
      rank.lists = read_lists(g);
      rank.lists.rebuilds_since_reorder = g.int_attribute("rebuilds_since_reorder");
      rank.decomposition = g.read_uint8s("decomposition");
      c.ranks.push_back(std::move(rank));
    }
  }

  const Hdf5Group metadata = file.group("metadata");
  for (const std::string& key : metadata.attribute_names()) c.metadata[key] = metadata.string_attribute(key);
  return c;
}

void restore_walls(Simulation& simulation, const Checkpoint& c) {
  const std::vector<Wall>& walls = simulation.walls();
  if (walls.size() != c.walls.size())
    throw InputError(fmt::format("checkpoint: it holds {} walls, the simulation has {}; build the simulation as the "
                                 "checkpointed run did",
                                 c.walls.size(), walls.size()));
  for (std::size_t k = 0; k < walls.size(); ++k) {
    if (walls[k].name != c.walls[k].name)
      throw InputError(fmt::format("checkpoint: wall {} is '{}' in the checkpoint but '{}' in the simulation", k,
                                   c.walls[k].name, walls[k].name));
  }
  if (simulation.time_step() != c.time_step)
    throw InputError(fmt::format("checkpoint: time step {} s differs from the simulation's {} s; the resumed run would "
                                 "not continue the checkpointed one",
                                 c.time_step, simulation.time_step()));
  for (std::size_t k = 0; k < walls.size(); ++k)
    simulation.restore_wall_state(k, c.walls[k].origin, c.walls[k].displacement, c.walls[k].force, c.walls[k].torque,
                                  c.walls[k].current_velocity);
}

void restore_checkpoint(Simulation& simulation, Checkpoint c) {
  restore_walls(simulation, c);
  // A simulation built with bodies and a checkpoint without: its particles would go on as free
  // spheres, a different run. (A checkpoint's bodies into a simulation without them is a resume
  // during a pour of clumps: the bodies were added as the run went.)
  if (c.bodies.empty() && !simulation.bodies().empty())
    throw InputError(fmt::format("checkpoint: it holds no rigid bodies, the simulation has {}; build the simulation "
                                 "as the checkpointed run did (a checkpoint of a run of clumps written before "
                                 "checkpoints held bodies cannot resume it)",
                                 simulation.bodies().size()));
  const std::size_t n = c.particles.size();
  // Lists that do not match the particles: particles were added after the last step and the
  // next step rebuilds. Assigning the particles afterwards (particles_mutable) leaves them invalid.
  const bool lists_match = c.lists.position_at_build.size() == n && c.lists.pairs.first.size() == n + 1;

  // The bodies before the particles and the lists: restore() finds their members among the particles
  // and sums the members' loads onto them. Their members are located here too, for a checkpoint that
  // never stepped: its first step places the members before a list build would locate them.
  if (!c.bodies.empty()) {
    c.bodies.locate_members(c.particles.id);
    simulation.restore_bodies(std::move(c.bodies));
  }

  // A checkpoint of a simulation that never stepped: the fresh one is already in that state, with
  // its set-up (initial forces) still to come.
  if (c.stats.steps == 0 && c.stats.rebuilds == 0) {
    simulation.particles_mutable() = std::move(c.particles);
    return;
  }
  simulation.particles_mutable() = std::move(c.particles);
  if (c.histories) {
    simulation.resume_from_histories(c.time, c.stats, std::move(*c.histories));
    return;
  }
  simulation.restore(c.time, c.stats, std::move(c.lists));
  if (!lists_match) simulation.particles_mutable();  // marks the lists for a rebuild at the next step
}

}  // namespace trapdem
