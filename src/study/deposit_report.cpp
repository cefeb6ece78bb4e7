#include "study/deposit_report.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "experiment/centrifuge_frame.hpp"
#include "experiment/run_folder.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot.hpp"

namespace trapdem {

namespace {

// m/s^2 downward at a position, for a snapshot of `stage`: 1 g while the fill is poured and settles,
// then (spin-up done, lowering) spin_up.g_level g, uniform or in the centrifuge's frame at its final
// spin (centrifugal only: the Euler term is gone once the spin is constant).
std::function<double(const Vec3&)> downward_acceleration(const ExperimentConfig& e, const std::string& stage) {
  const double g = ExperimentConfig::standard_gravity;
  if (stage == "pluviation" || stage == "settling") return [g](const Vec3&) { return g; };
  if (!e.centrifuge.enabled) return [a = e.spin_up.g_level * g](const Vec3&) { return a; };
  const FrameKick full_spin(centrifuge_frame(e, 0.0, false), 0.0, 0.0);
  return [full_spin](const Vec3& x) { return -full_spin.acceleration(x).z; };
}

}  // namespace

std::vector<DepositAtSnapshot> measure_run_deposit(const std::filesystem::path& run_dir) {
  const RunFolder folder(run_dir);
  const ExperimentConfig specimen = folder.specimen("the deposit needs the box");
  if (!folder.has_snapshots())
    throw InputError(fmt::format("{}: no snapshots.h5; the deposit is measured on a run's snapshots", run_dir.string()));
  DepositSettings settings;
  settings.box_width = specimen.box.width;
  settings.box_depth = specimen.box.depth;
  settings.periodic_depth = specimen.box.periodic_depth;
  std::vector<DepositAtSnapshot> out;
  for (const SnapshotInfo& info : list_snapshots(folder.snapshots_h5())) {
    const bool lowering = info.stage == "lowering";
    if (lowering && info.trapdoor_displacement > 0.0) break;
    const Snapshot s = read_snapshot(folder.snapshots_h5(), info.name);
    settings.solid_density = specimen.material.density;
    settings.downward_acceleration = downward_acceleration(specimen, info.stage);
    out.push_back({info.name, info.stage, info.time, measure_deposit(s, settings)});
    if (lowering) break;
  }
  if (out.empty())
    throw InputError(fmt::format("{}: no snapshot before the trapdoor moved", folder.snapshots_h5().string()));
  return out;
}

std::string deposit_table(const std::vector<DepositAtSnapshot>& deposits) {
  std::string t = fmt::format("{:<10} {:<11} {:>8} {:>9} {:>10} {:>9} {:>7} {:>8} {:>9} {:>12} {:>13}\n", "snapshot",
                              "stage", "time s", "particles", "surface mm", "rough mm", "phi", "Z", "rattlers",
                              "overlap % d", "sigma_v0 kPa");
  for (const DepositAtSnapshot& d : deposits) {
    const DepositMetrics& m = d.metrics;
    t += fmt::format("{:<10} {:<11} {:>8.4f} {:>9} {:>10.2f} {:>9.2f} {:>7.4f} {:>8.3f} {:>8.1f}% {:>5.3f}/{:<6.3f} {:>13.3f}\n",
                     d.snapshot, d.stage, d.time, m.particles, 1e3 * m.surface_height, 1e3 * m.surface_roughness,
                     m.bulk_solid_fraction, m.bulk_coordination, 100.0 * m.bulk_rattler_fraction, 100.0 * m.mean_overlap,
                     100.0 * m.max_overlap, 1e-3 * m.base_geostatic_stress);
  }
  t += "phi, Z, rattlers: the bulk layer (5 mean diameters above the base to 5 below the surface); Z counts\n"
       "particle contacts (overlap > 0), rattlers have fewer than two; overlap: mean/largest over all particle\n"
       "contacts, in % of the pair's mean diameter; sigma_v0: the geostatic vertical stress at the base, the\n"
       "deposit's weight over the plan area (1 g while pouring and settling, then the run's g level, in the\n"
       "centrifuge's frame when [centrifuge] is on; deposit.json has it with height).\n";
  return t;
}

std::filesystem::path write_deposit_json(const std::filesystem::path& run_dir,
                                         const std::vector<DepositAtSnapshot>& deposits) {
  Json list = Json::array();
  for (const DepositAtSnapshot& d : deposits) {
    const DepositMetrics& m = d.metrics;
    Json profile = Json::array();
    for (const DepositBin& b : m.profile) {
      Json bin = Json::object();
      bin.set("z_low_m", b.z_low);
      bin.set("z_high_m", b.z_high);
      bin.set("solid_fraction", b.solid_fraction);
      bin.set("coordination", b.coordination);
      bin.set("particles", b.particles);
      bin.set("geostatic_stress_pa", b.geostatic_stress);
      profile.push_back(std::move(bin));
    }
    Json j = Json::object();
    j.set("snapshot", d.snapshot);
    j.set("stage", d.stage);
    j.set("time_s", d.time);
    j.set("particles", m.particles);
    j.set("mean_diameter_m", m.mean_diameter);
    j.set("surface_height_m", m.surface_height);
    j.set("surface_roughness_m", m.surface_roughness);
    j.set("bulk_z_low_m", m.bulk_z_low);
    j.set("bulk_z_high_m", m.bulk_z_high);
    j.set("bulk_solid_fraction", m.bulk_solid_fraction);
    j.set("bulk_coordination", m.bulk_coordination);
    j.set("bulk_rattler_fraction", m.bulk_rattler_fraction);
    j.set("contacts", m.contacts);
    j.set("mean_overlap_of_diameter", m.mean_overlap);
    j.set("max_overlap_of_diameter", m.max_overlap);
    j.set("base_geostatic_stress_pa", m.base_geostatic_stress);
    j.set("profile", std::move(profile));
    list.push_back(std::move(j));
  }
  Json doc = Json::object();
  doc.set("deposits", std::move(list));
  const std::filesystem::path path = run_dir / "deposit.json";
  write_text_atomically(path, doc.dump() + "\n");
  return path;
}

}  // namespace trapdem
