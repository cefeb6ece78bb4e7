#include "analysis/field_history.hpp"

#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "analysis/grid_interpolation.hpp"
#include "core/errors.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

constexpr const char* kFormat = "trapdem-field-history";
constexpr std::int64_t kVersion = 1;

// Appends one grid field to a stack as float32 (the fields need ~7 significant digits at most:
// displacements to 0.1 um in a 0.4 m box, strains to 1e-7).
void append_layer(FloatStack& stack, const GridField& field) {
  stack.rows = field.grid.nz;
  stack.columns = field.grid.nx;
  ++stack.layers;
  for (double v : field.value) stack.value.push_back(static_cast<float>(v));
}

}  // namespace

FieldHistory field_history(const std::vector<double>& displacements, const FrameLoader& load_frame,
                           const SpecimenGeometry& geometry, AnalysisSettings settings, double spacing) {
  if (displacements.size() < 2)
    throw InputError(fmt::format("the field history needs a reference and at least one later snapshot; found {}",
                                 displacements.size()));
  settings.at = std::numeric_limits<double>::quiet_NaN();
  settings.incremental = false;
  const FrameChoice choice = choose_frames(displacements, settings);  // the reference; throws if none after it

  FieldHistory h;
  h.case_name = geometry.name;
  std::vector<AnalysisFrame> pair{load_frame(choice.reference)};
  h.reference_label = pair.front().label;
  h.reference_displacement = pair.front().trapdoor_displacement;
  for (std::size_t k = choice.reference + 1; k < displacements.size(); ++k) {
    pair.resize(1);
    pair.push_back(load_frame(k));
    const AnalysisResult r = analyze_frames(pair, geometry, settings);
    if (h.labels.empty()) {  // the first layer fixes the view and the grid for all of them
      h.view = view_name(r.settings.view);
      h.front_depth = r.settings.front_depth;
      h.mean_diameter = r.mean_diameter;
      const double step = spacing > 0.0 ? spacing : kFieldHistorySpacingDiameters * r.mean_diameter;
      h.grid = grid_covering(r.points.position, step);
    }
    append_layer(h.vertical_displacement,
                 interpolate_nodal_field(r.mesh.mesh, r.points.position, vertical_displacements(r.points), h.grid));
    append_layer(h.gamma_max, sample_triangle_field(r.mesh.mesh, r.points.position, r.gamma_max, h.grid));
    append_layer(h.volumetric_strain, sample_triangle_field(r.mesh.mesh, r.points.position, r.volumetric, h.grid));
    h.labels.push_back(r.at_label);
    h.trapdoor_displacement.push_back(r.at_displacement);
    h.matched_particles.push_back(r.matched_particles);
  }
  return h;
}

FieldHistory field_history_of_snapshot_file(const fs::path& h5, const SpecimenGeometry& geometry,
                                            const AnalysisSettings& settings, double spacing) {
  const std::vector<SnapshotInfo> infos = list_snapshots(h5);
  std::vector<double> displacements;
  for (const SnapshotInfo& info : infos) displacements.push_back(info.trapdoor_displacement);
  const FrameLoader load = [&](std::size_t k) {
    return AnalysisFrame{infos[k].name, infos[k].trapdoor_displacement, grain_view(read_snapshot(h5, infos[k].name))};
  };
  return field_history(displacements, load, geometry, settings, spacing);
}

void write_field_history(const fs::path& h5, const FieldHistory& h) {
  if (h5.has_parent_path()) fs::create_directories(h5.parent_path());
  write_atomically(h5, [&](const fs::path& temporary) {
    Hdf5File file = Hdf5File::create_in_memory(h5);
    file.set_string_attribute("format", kFormat);
    file.set_int_attribute("version", kVersion);
    file.set_string_attribute("case", h.case_name);
    file.set_string_attribute("view", h.view);
    file.set_double_attribute("front_depth", h.front_depth);
    file.set_double_attribute("mean_diameter", h.mean_diameter);
    file.set_string_attribute("reference_snapshot", h.reference_label);
    file.set_double_attribute("reference_displacement", h.reference_displacement);
    file.set_string_attribute("layout",
                              "fields[layer, row j, column i] at x = x0 + i * spacing, z = z0 + j * spacing; "
                              "NaN outside the kept triangles");
    file.set_string_attribute("sign_convention", "w positive up; strain compression positive; gamma engineering shear");
    const Hdf5Group grid = file.create_group("grid");
    grid.set_double_attribute("x0", h.grid.x0);
    grid.set_double_attribute("z0", h.grid.z0);
    grid.set_double_attribute("spacing", h.grid.spacing);
    grid.set_int_attribute("nx", static_cast<std::int64_t>(h.grid.nx));
    grid.set_int_attribute("nz", static_cast<std::int64_t>(h.grid.nz));
    file.write_strings("snapshot", h.labels);
    file.write_doubles("trapdoor_displacement", h.trapdoor_displacement, "m");
    std::vector<std::int64_t> matched(h.matched_particles.begin(), h.matched_particles.end());
    file.write_int64s("matched_particles", matched);
    file.write_float_stack("vertical_displacement", h.vertical_displacement, "m");
    file.write_float_stack("gamma_max", h.gamma_max, "1");
    file.write_float_stack("volumetric_strain", h.volumetric_strain, "1");
    file.write_image(temporary);
  });
}

FieldHistory read_field_history(const fs::path& h5) {
  const Hdf5File file = Hdf5File::open_read(h5);
  if (!file.has_attribute("format") || file.string_attribute("format") != kFormat)
    throw FileError(fmt::format("{}: not a field history (expected the root attribute format = \"{}\")", h5.string(),
                                kFormat));
  if (file.int_attribute("version") != kVersion)
    throw FileError(fmt::format("{}: field history version {}; this trapdem reads version {}", h5.string(),
                                file.int_attribute("version"), kVersion));
  FieldHistory h;
  h.case_name = file.string_attribute("case");
  h.view = file.string_attribute("view");
  h.front_depth = file.double_attribute("front_depth");
  h.mean_diameter = file.double_attribute("mean_diameter");
  h.reference_label = file.string_attribute("reference_snapshot");
  h.reference_displacement = file.double_attribute("reference_displacement");
  const Hdf5Group grid = file.group("grid");
  h.grid.x0 = grid.double_attribute("x0");
  h.grid.z0 = grid.double_attribute("z0");
  h.grid.spacing = grid.double_attribute("spacing");
  const std::int64_t nx = grid.int_attribute("nx"), nz = grid.int_attribute("nz");
  if (nx < 0 || nz < 0 || !(h.grid.spacing > 0.0))
    throw FileError(fmt::format("{}: /grid: expected nx, nz >= 0 and a positive spacing; found {}, {}, {}",
                                h5.string(), nx, nz, h.grid.spacing));
  h.grid.nx = static_cast<std::size_t>(nx);
  h.grid.nz = static_cast<std::size_t>(nz);
  h.labels = file.read_strings("snapshot");
  h.trapdoor_displacement = file.read_doubles("trapdoor_displacement");
  for (std::int64_t m : file.read_int64s("matched_particles")) h.matched_particles.push_back(static_cast<std::size_t>(m));
  h.vertical_displacement = file.read_float_stack("vertical_displacement");
  h.gamma_max = file.read_float_stack("gamma_max");
  h.volumetric_strain = file.read_float_stack("volumetric_strain");
  const std::size_t n = h.labels.size();
  if (h.trapdoor_displacement.size() != n || h.matched_particles.size() != n)
    throw FileError(fmt::format("{}: {} snapshot names but {} displacements and {} particle counts", h5.string(), n,
                                h.trapdoor_displacement.size(), h.matched_particles.size()));
  for (const auto& [name, stack] : {std::pair{"vertical_displacement", &h.vertical_displacement},
                                    std::pair{"gamma_max", &h.gamma_max},
                                    std::pair{"volumetric_strain", &h.volumetric_strain}}) {
    if (stack->layers != n || stack->rows != h.grid.nz || stack->columns != h.grid.nx)
      throw FileError(fmt::format("{}: /{} is {} x {} x {}; expected {} layers of the {} x {} grid", h5.string(), name,
                                  stack->layers, stack->rows, stack->columns, n, h.grid.nz, h.grid.nx));
  }
  return h;
}

}  // namespace trapdem
