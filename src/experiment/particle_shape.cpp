#include "experiment/particle_shape.hpp"

#include <map>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/rigid/clump_shapes.hpp"
#include "io/config.hpp"

namespace trapdem {

namespace {

// Each kind's keys (beside `kind`): a key given for another kind is refused by name.
const std::map<std::string, std::vector<std::string>>& keys_by_kind() {
  static const std::map<std::string, std::vector<std::string>> keys{
      {"sphere", {}},
      {"dimer", {"aspect"}},
      {"tetrahedral", {"spacing"}},
      {"sub_angular", {"satellites", "satellite_radius", "elongation", "flatness"}},
      {"file", {"file"}}};
  return keys;
}

}  // namespace

double ParticleShape::bounding_ratio() const {
  return clump ? clump->bounding_radius() / (0.5 * clump->volume_equivalent_diameter()) : 1.0;
}

std::string ParticleShape::describe() const {
  if (!clump) return "spheres";
  return fmt::format("rigid clumps, {} ({}; {} member spheres, bounding radius {:.3f} x the volume-equivalent radius, "
                     "principal moments {:.4f} {:.4f} {:.4f} x m d_eq^2)",
                     kind, clump->name, clump->members.size(), bounding_ratio(),
                     clump->principal_inertia.x / clump->volume, clump->principal_inertia.y / clump->volume,
                     clump->principal_inertia.z / clump->volume);
}

ParticleShape read_particle_shape(Config& t) {
  ParticleShape shape;
  std::vector<std::string> kinds;
  for (const auto& [kind, keys] : keys_by_kind()) kinds.push_back(kind);
  shape.kind = t.get_choice("kind", "sphere", kinds);
  for (const auto& [kind, keys] : keys_by_kind()) {
    if (kind == shape.kind) continue;
    for (const std::string& key : keys)
      if (t.has(key)) t.fail(key, fmt::format("no {} with kind = \"{}\" (read only with kind = \"{}\")", key, shape.kind, kind));
  }
  std::vector<ClumpMember> members;
  std::string source;
  try {
    if (shape.kind == "sphere") return shape;
    if (shape.kind == "dimer") {
      const double aspect = t.get_double("aspect", 1.5, "", Range{1.0, 2.0, true, false});
      members = dimer_members(aspect);
      source = fmt::format("dimer, aspect {}", aspect);
    } else if (shape.kind == "tetrahedral") {
      const double spacing = t.get_double("spacing", 1.0, "radii", Range{0.0, 2.0, false, false});
      members = tetrahedral_members(spacing);
      source = fmt::format("tetrahedral, spacing {} radii", spacing);
    } else if (shape.kind == "sub_angular") {
      const int satellites = int(t.get_int("satellites", 6, Range::closed(2, 20)));
      const double radius = t.get_double("satellite_radius", 0.5, "core radii", Range::unit_open_closed());
      const double elongation = t.get_double("elongation", 1.0, "", Range::closed(0.5, 2.0));
      const double flatness = t.get_double("flatness", 1.0, "", Range::closed(0.5, 2.0));
      members = sub_angular_members(satellites, radius, elongation, flatness);
      source = fmt::format("sub-angular grain, {} satellites of radius {}, elongation {}, flatness {}", satellites,
                           radius, elongation, flatness);
    } else {
      const std::string file = t.require_path("file");
      members = read_clump_members(file);
      source = file;
    }
    if (t.has_errors()) return ParticleShape{};  // a refused value: reading goes on to find the others
    shape.clump = std::make_shared<const ClumpTemplate>(make_clump_template(members, source).scaled_to(1.0));
  } catch (const InputError& e) {
    t.fail(shape.kind == "file" ? "file" : "kind", e.what());
    return ParticleShape{};
  }
  return shape;
}

}  // namespace trapdem
