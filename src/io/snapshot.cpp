#include "io/snapshot.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_set>
#include <utility>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/text_escape.hpp"
#include "io/atomic_file.hpp"
#include "io/hdf5_file.hpp"
#include "io/particle_checks.hpp"

namespace trapdem {

namespace fs = std::filesystem;

namespace {

constexpr const char* kFormat = "trapdem-snapshots";
constexpr std::int64_t kVersion = 2;  // 2: each snapshot in its own file, linked from the index
constexpr const char* kRoot = "snapshots";
// 0, 1, 2, ... (int32): the vertex list of the XDMF's Polyvertex topology. ParaView's XDMF 3 reader
// makes no cells from a Polyvertex topology without one (points, 0 cells: its default Surface view
// is then empty), so each grid takes the first N entries of this array (an XDMF hyperslab).
constexpr const char* kVertexIndex = "vertex_index";

// Makes the file's vertex index at least n long (it only grows: the first n entries of a longer
// one are the same).
void ensure_vertex_index(const Hdf5Group& root, std::size_t n) {
  if (root.has(kVertexIndex) && root.dataset_length(kVertexIndex) >= n) return;
  if (root.has(kVertexIndex)) root.remove(kVertexIndex);
  std::vector<std::uint32_t> index(n);
  for (std::size_t i = 0; i < n; ++i) index[i] = static_cast<std::uint32_t>(i);
  root.write_uint32s(kVertexIndex, index);
}

std::string group_name(std::size_t index) { return fmt::format("{:06d}", index); }

// Whether a snapshot attribute is there to read. trapdem writes every one of them, so in its own
// files (`own`: the index says format = "trapdem-snapshots") a missing one is damage, named; a file
// written by another tool may leave them out (docs/output.md: they default to 0 and "").
bool has_snapshot_attribute(const Hdf5Group& g, const char* name, bool own) {
  if (g.has_attribute(name)) return true;
  if (own)
    throw FileError(fmt::format("{}: attribute '{}' missing or unreadable: trapdem writes it with every snapshot "
                                "(the file is damaged)", g.describe(), name));
  return false;
}

SnapshotInfo info_of(const Hdf5Group& g, const std::string& name, bool own) {
  SnapshotInfo info;
  info.name = name;
  info.time = has_snapshot_attribute(g, "time", own) ? g.double_attribute("time") : 0.0;
  info.stage = has_snapshot_attribute(g, "stage", own) ? g.string_attribute("stage") : "";
  info.trapdoor_displacement =
      has_snapshot_attribute(g, "trapdoor_displacement", own) ? g.double_attribute("trapdoor_displacement") : 0.0;
  info.step = has_snapshot_attribute(g, "step", own) ? g.int_attribute("step") : 0;
  if (!std::isfinite(info.time) || !std::isfinite(info.trapdoor_displacement))
    throw FileError(fmt::format("{}: time {} s, trapdoor_displacement {} m: expected finite numbers (the file is damaged)",
                                g.describe(), info.time, info.trapdoor_displacement));
  info.particle_count = g.dataset_length("id");
  info.has_body = g.has("body");
  return info;
}

// Whether the index is trapdem's own (format = "trapdem-snapshots").
bool written_by_trapdem(const Hdf5File& file) {
  return file.has_attribute("format") && file.string_attribute("format") == kFormat;
}

// Where a snapshot's datasets are, for the XDMF: "snapshots/000003.h5:/" (its own file, the index
// holding an external link) or "snapshots.h5:/snapshots/000003/" (a group inside the index: files
// written by other tools, or by trapdem before version 2).
std::string data_location(const Hdf5Group& root, const std::string& index_file_name, const std::string& name) {
  if (const auto target = root.external_link(name)) {
    std::string object = target->object;
    if (object.empty() || object.back() != '/') object += '/';
    return target->file + ":" + object;
  }
  return fmt::format("{}:/{}/{}/", index_file_name, kRoot, name);
}

std::vector<SnapshotInfo> list_in(const Hdf5File& file) {
  std::vector<SnapshotInfo> out;
  if (!file.has(kRoot)) return out;
  const Hdf5Group root = file.group(kRoot);
  const std::string index_name = fs::path(file.file_name()).filename().string();
  for (const std::string& name : root.children()) {
    out.push_back(info_of(root.group(name), name, written_by_trapdem(file)));
    out.back().location = data_location(root, index_name, name);
  }
  return out;
}

// snapshots.h5 -> snapshots/ beside it: the snapshots' own files.
fs::path data_folder_of(const fs::path& h5_path) {
  fs::path folder = h5_path;
  folder.replace_extension();
  return folder;
}

// The datasets and attributes of one snapshot, in `g` (the root of the snapshot's own file).
void write_snapshot_data(const Hdf5Group& g, const Snapshot& s) {
  g.set_double_attribute("time", s.time);
  g.set_string_attribute("stage", s.stage);
  g.set_double_attribute("trapdoor_displacement", s.trapdoor_displacement);
  g.set_int_attribute("step", s.step);
  g.write_int64s("id", s.id);
  g.write_vec3s("position", s.position, "m");
  g.write_vec3s("velocity", s.velocity, "m/s");
  g.write_vec3s("angular_velocity", s.angular_velocity, "rad/s");
  g.write_doubles("radius", s.radius, "m");
  if (s.image.empty()) g.write_int3s("image", std::vector<Int3>(s.size()));
  else g.write_int3s("image", s.image);
  // A run of clumps: each particle's body, and the bodies themselves (a run of spheres has neither).
  if (!s.body.empty()) g.write_int64s("body", s.body);
  if (!s.bodies.empty()) {
    const Hdf5Group b = g.create_group("bodies");
    b.write_int64s("id", s.bodies.id);
    b.write_vec3s("position", s.bodies.position, "m");
    b.write_doubles("radius", s.bodies.radius, "m");
    b.write_vec3s("velocity", s.bodies.velocity, "m/s");
    b.write_quaternions("orientation", s.bodies.orientation);
    b.write_vec3s("angular_velocity", s.bodies.angular_velocity, "rad/s");
  }
}

SnapshotBodies read_bodies(const Hdf5Group& g) {
  SnapshotBodies b;
  b.id = g.read_int64s("id");
  b.position = g.read_vec3s("position");
  b.radius = g.read_doubles("radius");
  b.velocity = g.read_vec3s("velocity");
  b.orientation = g.read_quaternions("orientation");
  b.angular_velocity = g.read_vec3s("angular_velocity");
  const std::size_t n = b.id.size();
  for (std::size_t size : {b.position.size(), b.radius.size(), b.velocity.size(), b.orientation.size(), b.angular_velocity.size()}) {
    if (size != n)
      throw FileError(
          fmt::format("{}: body datasets differ in length ({} ids, a dataset of {})", g.describe(), n, size));
  }
  check_body_rows(g.describe(), b.id, b.position, b.velocity, b.orientation);
  check_finite_column(g.describe(), "angular_velocity (rad/s)", b.id, b.angular_velocity, "body");
  check_positive_column(g.describe(), "radius (m)", b.id, b.radius, "body");
  return b;
}

// Each particle's body is one of the snapshot's bodies (or none, kNoBodyId); without the bodies
// (a file of another tool may give the ids alone) only the value's range is checked.
void check_particle_bodies(const std::string& where, const Snapshot& s) {
  const std::unordered_set<std::int64_t> bodies(s.bodies.id.begin(), s.bodies.id.end());
  for (std::size_t k = 0; k < s.body.size(); ++k) {
    const std::int64_t b = s.body[k];
    const bool known = b == kNoBodyId || (s.bodies.empty() ? b >= 0 : bodies.count(b) > 0);
    if (!known)
      throw FileError(fmt::format("{}: row {} (particle id {}): body {}: expected {} or {} (no body) (the file is "
                                  "damaged or was not written by trapdem)",
                                  where, k, s.id[k], b,
                                  s.bodies.empty() ? "a body id >= 0" : "the id of one of the snapshot's bodies",
                                  kNoBodyId));
  }
}

fs::path xdmf_path_of(const fs::path& h5_path) {
  fs::path xmf = h5_path;
  xmf.replace_extension(".xmf");
  return xmf;
}

}  // namespace

Snapshot make_snapshot(const Particles& p, double time, std::string stage, double trapdoor_displacement,
                       std::int64_t step) {
  Snapshot s;
  s.time = time;
  s.stage = std::move(stage);
  s.trapdoor_displacement = trapdoor_displacement;
  s.step = step;
  s.id = p.id;
  s.position = p.position;
  s.velocity = p.velocity;
  s.angular_velocity = p.angular_velocity;
  s.radius = p.radius;
  s.image = p.image;
  return s;
}

Snapshot make_snapshot(const Particles& p, const RigidBodies& bodies, double time, std::string stage,
                       double trapdoor_displacement, std::int64_t step) {
  Snapshot s = make_snapshot(p, time, std::move(stage), trapdoor_displacement, step);
  if (bodies.empty()) return s;
  // Member id -> body id, sorted: one binary search per particle.
  std::vector<std::pair<std::int64_t, std::int64_t>> body_of_member;
  body_of_member.reserve(bodies.member_count());
  for (std::size_t b = 0; b < bodies.size(); ++b)
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m)
      body_of_member.emplace_back(bodies.member_id[m], bodies.id[b]);
  std::sort(body_of_member.begin(), body_of_member.end());
  s.body.resize(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto it = std::lower_bound(body_of_member.begin(), body_of_member.end(), std::pair{p.id[i], std::int64_t{}},
                                     [](const auto& a, const auto& b) { return a.first < b.first; });
    s.body[i] = it != body_of_member.end() && it->first == p.id[i] ? it->second : kNoBodyId;
  }
  s.bodies.id = bodies.id;
  s.bodies.position = bodies.position;
  s.bodies.radius.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b)
    s.bodies.radius[b] = std::cbrt(3.0 * bodies.volume[b] / (4.0 * std::numbers::pi));
  s.bodies.velocity = bodies.velocity;
  s.bodies.orientation = bodies.orientation;
  s.bodies.angular_velocity.resize(bodies.size());
  for (std::size_t b = 0; b < bodies.size(); ++b) s.bodies.angular_velocity[b] = bodies.angular_velocity(b);
  return s;
}

std::string append_snapshot(const fs::path& h5_path, const Snapshot& s) {
  const std::size_t n = s.size();
  if (s.position.size() != n || s.velocity.size() != n || s.angular_velocity.size() != n || s.radius.size() != n ||
      (!s.image.empty() && s.image.size() != n) || (!s.body.empty() && s.body.size() != n))
    throw FileError(fmt::format("{}: snapshot arrays differ in length ({} ids)", h5_path.string(), n));
  const std::size_t bodies = s.bodies.size();
  if (s.bodies.position.size() != bodies || s.bodies.radius.size() != bodies || s.bodies.velocity.size() != bodies ||
      s.bodies.orientation.size() != bodies || s.bodies.angular_velocity.size() != bodies)
    throw FileError(fmt::format("{}: snapshot body arrays differ in length ({} body ids)", h5_path.string(), bodies));
  std::error_code ec;
  const bool fresh = !fs::exists(h5_path, ec);
  const std::string name = group_name(fresh ? 0 : list_snapshots(h5_path).size());

  // 1. The snapshot's own file. A file of that name left by an append that was killed before step
  // 2 is not in the index: it is replaced.
  const fs::path folder = data_folder_of(h5_path);
  fs::create_directories(folder, ec);
  if (ec) throw FileError(fmt::format("cannot create the snapshot folder {}: {}", folder.string(), ec.message()));
  const fs::path data_file = folder / (name + ".h5");
  write_atomically(data_file, [&](const fs::path& temporary) {
    Hdf5File file = Hdf5File::create_in_memory(data_file);
    write_snapshot_data(file, s);
    file.write_image(temporary);
  });

  // 2. The index: one more link. Small (links and the vertex index), so rewriting it whole is cheap.
  write_atomically(h5_path, [&](const fs::path& temporary) {
    Hdf5File file = fresh ? Hdf5File::create_in_memory(h5_path) : Hdf5File::open_in_memory(h5_path);
    if (fresh) {
      file.set_string_attribute("format", kFormat);
      file.set_int_attribute("version", kVersion);
    }
    const Hdf5Group root = file.has(kRoot) ? file.group(kRoot) : file.create_group(kRoot);
    root.create_external_link(name, (folder.filename() / (name + ".h5")).string(), "/");
    ensure_vertex_index(file, n);
    file.write_image(temporary);
  });

  // 3. The XDMF companion.
  write_snapshot_xdmf(h5_path);
  return name;
}

void truncate_snapshots(const fs::path& h5_path, std::int64_t last_step) {
  std::error_code ec;
  if (!fs::exists(h5_path, ec)) return;
  const std::vector<SnapshotInfo> infos = list_snapshots(h5_path);
  std::size_t keep = 0;
  while (keep < infos.size() && infos[keep].step <= last_step) ++keep;
  keep_snapshots(h5_path, keep);
}

void keep_snapshots(const fs::path& h5_path, std::size_t keep) {
  std::error_code ec;
  if (!fs::exists(h5_path, ec)) return;
  const std::vector<SnapshotInfo> infos = list_snapshots(h5_path);
  if (keep >= infos.size()) return;
  std::vector<std::string> dropped;
  for (std::size_t k = keep; k < infos.size(); ++k) dropped.push_back(infos[k].name);
  std::vector<fs::path> orphans;  // the dropped snapshots' own files, removed once the index no longer names them
  write_atomically(h5_path, [&](const fs::path& temporary) {
    Hdf5File file = Hdf5File::open_in_memory(h5_path);
    const Hdf5Group root = file.group(kRoot);
    for (const std::string& name : dropped) {
      if (const auto target = root.external_link(name)) orphans.push_back(h5_path.parent_path() / target->file);
      root.remove(name);
    }
    file.write_image(temporary);
  });
  if (keep == 0) {
    fs::remove(h5_path, ec);
    fs::remove(xdmf_path_of(h5_path), ec);
  } else {
    write_snapshot_xdmf(h5_path);
  }
  for (const fs::path& orphan : orphans) fs::remove(orphan, ec);
}

std::vector<SnapshotInfo> list_snapshots(const fs::path& h5_path) { return list_in(Hdf5File::open_read(h5_path)); }

Snapshot grain_view(const Snapshot& s) {
  if (s.bodies.empty()) return s;
  Snapshot g;
  g.time = s.time;
  g.stage = s.stage;
  g.trapdoor_displacement = s.trapdoor_displacement;
  g.step = s.step;
  g.id = s.bodies.id;
  g.position = s.bodies.position;
  g.velocity = s.bodies.velocity;
  g.angular_velocity = s.bodies.angular_velocity;
  g.radius = s.bodies.radius;
  g.image.assign(s.bodies.size(), Int3{});  // bodies run with bounded axes only
  return g;
}

Snapshot read_snapshot(const fs::path& h5_path, const std::string& name) {
  const Hdf5File file = Hdf5File::open_read(h5_path);
  const Hdf5Group g = file.group(kRoot).group(name);
  const SnapshotInfo info = info_of(g, name, written_by_trapdem(file));
  Snapshot s;
  s.time = info.time;
  s.stage = info.stage;
  s.trapdoor_displacement = info.trapdoor_displacement;
  s.step = info.step;
  s.id = g.read_int64s("id");
  s.position = g.read_vec3s("position");
  s.radius = g.read_doubles("radius");
  const std::size_t n = s.id.size();
  s.velocity = g.has("velocity") ? g.read_vec3s("velocity") : std::vector<Vec3>(n);
  s.angular_velocity = g.has("angular_velocity") ? g.read_vec3s("angular_velocity") : std::vector<Vec3>(n);
  s.image = g.has("image") ? g.read_int3s("image") : std::vector<Int3>(n);
  for (std::size_t size : {s.position.size(), s.radius.size(), s.velocity.size(), s.angular_velocity.size(),
                           s.image.size()}) {
    if (size != n)
      throw FileError(fmt::format("{}: datasets differ in length ({} ids, a dataset of {})", g.describe(), n, size));
  }
  check_particle_rows(g.describe(), s.id, s.position, s.radius, s.velocity, s.angular_velocity);
  // A run of clumps (absent in a run of spheres and in files written before snapshots held bodies).
  if (g.has("bodies")) s.bodies = read_bodies(g.group("bodies"));
  if (g.has("body")) {
    s.body = g.read_int64s("body");
    if (s.body.size() != n)
      throw FileError(fmt::format("{}: datasets differ in length ({} ids, a dataset of {})", g.describe("body"), n,
                                  s.body.size()));
    check_particle_bodies(g.describe(), s);
  }
  return s;
}

std::vector<Snapshot> read_snapshots(const fs::path& h5_path) {
  std::vector<Snapshot> out;
  for (const SnapshotInfo& info : list_snapshots(h5_path)) out.push_back(read_snapshot(h5_path, info.name));
  return out;
}

std::string snapshot_xdmf(const std::string& h5_file_name, const std::vector<SnapshotInfo>& snapshots,
                          std::size_t vertex_index_length) {
  const std::string file = markup_escape(h5_file_name);
  std::string x;
  x += "<?xml version=\"1.0\" ?>\n";
  x += "<!-- trapdem particle snapshots: the index " + file + " and the files it links (see docs/output.md) -->\n";
  x += "<Xdmf Version=\"3.0\">\n  <Domain>\n";
  x += "    <Grid Name=\"particles\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (const SnapshotInfo& s : snapshots) {
    if (s.particle_count == 0) continue;
    const std::size_t n = s.particle_count;
    const std::string base =
        markup_escape(s.location.empty() ? fmt::format("{}:/{}/{}/", h5_file_name, kRoot, s.name) : s.location);
    auto item = [&](const char* dataset, int columns, const char* type) {
      const std::string dims = columns > 1 ? fmt::format("{} {}", n, columns) : fmt::format("{}", n);
      return fmt::format(
          "          <DataItem Dimensions=\"{}\" NumberType=\"{}\" Precision=\"8\" Format=\"HDF\">{}{}</DataItem>\n",
          dims, type, base, dataset);
    };
    auto attribute = [&](const char* name, const char* kind, int columns, const char* type) {
      return fmt::format("        <Attribute Name=\"{}\" AttributeType=\"{}\" Center=\"Node\">\n{}        </Attribute>\n",
                         name, kind, item(name, columns, type));
    };
    x += fmt::format("      <Grid Name=\"{}\" GridType=\"Uniform\">\n", s.name);
    x += fmt::format("        <Time Value=\"{}\"/>\n", s.time);
    x += fmt::format("        <Information Name=\"stage\" Value=\"{}\"/>\n", markup_escape(s.stage));
    x += fmt::format("        <Information Name=\"trapdoor_displacement\" Value=\"{}\"/>\n", s.trapdoor_displacement);
    x += fmt::format("        <Information Name=\"step\" Value=\"{}\"/>\n", s.step);
    x += fmt::format("        <Topology TopologyType=\"Polyvertex\" NumberOfElements=\"{}\" NodesPerElement=\"1\">\n", n);
    if (vertex_index_length >= n) {
      // Vertex i is particle row i: the first n entries of the vertex index (start 0, stride 1, count n).
      x += fmt::format("          <DataItem ItemType=\"HyperSlab\" Dimensions=\"{}\" Type=\"HyperSlab\">\n", n);
      x += fmt::format("            <DataItem Dimensions=\"3 1\" Format=\"XML\">0 1 {}</DataItem>\n", n);
      x += fmt::format("            <DataItem Dimensions=\"{}\" NumberType=\"UInt\" Precision=\"4\" Format=\"HDF\">{}:/{}</DataItem>\n",
                       vertex_index_length, file, kVertexIndex);
      x += "          </DataItem>\n";
    }
    x += "        </Topology>\n";
    x += "        <Geometry GeometryType=\"XYZ\">\n" + item("position", 3, "Float") + "        </Geometry>\n";
    x += attribute("radius", "Scalar", 1, "Float");
    x += attribute("id", "Scalar", 1, "Int");
    x += attribute("velocity", "Vector", 3, "Float");
    x += attribute("angular_velocity", "Vector", 3, "Float");
    if (s.has_body) x += attribute("body", "Scalar", 1, "Int");
    x += "      </Grid>\n";
  }
  x += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  return x;
}

void write_snapshot_xdmf(const fs::path& h5_path) {
  const Hdf5File file = Hdf5File::open_read(h5_path);
  const std::vector<SnapshotInfo> snapshots = list_in(file);
  const std::size_t vertex_index_length = file.has(kVertexIndex) ? file.dataset_length(kVertexIndex) : 0;
  write_text_atomically(xdmf_path_of(h5_path), snapshot_xdmf(h5_path.filename().string(), snapshots, vertex_index_length));
}

}  // namespace trapdem
