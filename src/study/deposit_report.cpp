#include "study/deposit_report.hpp"

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "experiment/run_folder.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot.hpp"

namespace trapdem {

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
    out.push_back({info.name, info.stage, info.time, measure_deposit(s, settings)});
    if (lowering) break;
  }
  if (out.empty())
    throw InputError(fmt::format("{}: no snapshot before the trapdoor moved", folder.snapshots_h5().string()));
  return out;
}

std::string deposit_table(const std::vector<DepositAtSnapshot>& deposits) {
  std::string t = fmt::format("{:<10} {:<11} {:>8} {:>9} {:>10} {:>9} {:>7} {:>8} {:>9} {:>12}\n", "snapshot", "stage",
                              "time s", "particles", "surface mm", "rough mm", "phi", "Z", "rattlers", "overlap % d");
  for (const DepositAtSnapshot& d : deposits) {
    const DepositMetrics& m = d.metrics;
    t += fmt::format("{:<10} {:<11} {:>8.4f} {:>9} {:>10.2f} {:>9.2f} {:>7.4f} {:>8.3f} {:>8.1f}% {:>5.3f}/{:<6.3f}\n",
                     d.snapshot, d.stage, d.time, m.particles, 1e3 * m.surface_height, 1e3 * m.surface_roughness,
                     m.bulk_solid_fraction, m.bulk_coordination, 100.0 * m.bulk_rattler_fraction, 100.0 * m.mean_overlap,
                     100.0 * m.max_overlap);
  }
  t += "phi, Z, rattlers: the bulk layer (5 mean diameters above the base to 5 below the surface); Z counts\n"
       "particle contacts (overlap > 0), rattlers have fewer than two; overlap: mean/largest over all particle\n"
       "contacts, in % of the pair's mean diameter.\n";
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
