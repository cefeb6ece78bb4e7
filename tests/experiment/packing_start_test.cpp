// Runs that start from a packing made elsewhere ([packing]): a LAMMPS data file and a LAMMPS dump
// written here, and a snapshot of a tiny run; each check of the packing with its message naming
// the particle id and the file line; a packing denser than a pour's in the neighbour search.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/json.hpp"
#include "experiment/folder_run.hpp"
#include "experiment/packing_input.hpp"
#include "experiment/trapdoor_experiment.hpp"
#include "io/config.hpp"
#include "io/lammps_data.hpp"
#include "io/snapshot.hpp"
#include "io/text_file.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace trapdem;
using trapdem::test::ScratchDir;

namespace {

const fs::path kTiny = fs::path(TRAPDEM_SOURCE_DIR) / "presets" / "tiny.toml";

// The tiny preset's box (80 x 14 x 60 mm) filled with a simple cubic lattice of 4 mm spheres 4.4 mm
// apart: 18 x 3 x `layers`, ids 101, 102, ... (not 1..N: the ids must be kept, not renumbered).
Particles lattice(int layers, double density = 2500.0) {
  Particles p;
  std::int64_t id = 101;
  for (int k = 0; k < layers; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 18; ++i)
        p.add(id++, Vec3{0.0022 + 0.0044 * i, 0.0024 + 0.0046 * j, 0.0022 + 0.0044 * k}, 0.002, density);
  return p;
}

// A short tiny run: settling and spin-up bounded, 0.5 mm of travel, snapshots at the start of lowering.
std::vector<std::string> short_run(const std::string& from, const std::string& format) {
  return {"packing.from=" + from, "packing.format=" + format, "settling.max_time=0.01",
          "spin_up.ramp_time=0.005", "trapdoor.travel=0.0005", "output.snapshot_displacements=[0.0]"};
}

ExperimentConfig config_with(const std::vector<std::string>& overrides) {
  Config c = Config::load_file(kTiny.string());
  c.apply_overrides(overrides);
  return ExperimentConfig::from(c);
}

std::string error_of(const std::vector<std::string>& overrides) {
  try {
    config_with(overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

bool run_folder(const std::vector<std::string>& overrides, const fs::path& out) {
  FolderRunOptions o;
  o.config_file = kTiny;
  o.overrides = overrides;
  o.out_dir = out;
  o.quiet = true;
  o.threads = 1;
  return run_in_folder(o);
}

std::set<std::int64_t> ids_of(const std::vector<std::int64_t>& ids) { return {ids.begin(), ids.end()}; }

void write_dump(const fs::path& path, const Particles& p, bool velocities) {
  std::ofstream out(path);
  out << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n" << p.size() << "\nITEM: BOX BOUNDS ff ff ff\n"
      << "0 0.08\n0 0.014\n0 0.045\nITEM: ATOMS id type x y z radius" << (velocities ? " vx vy vz" : "") << "\n";
  for (std::size_t i = 0; i < p.size(); ++i) {
    out << fmt::format("{} 1 {:.17g} {:.17g} {:.17g} {:.17g}", p.id[i], p.position[i].x, p.position[i].y,
                       p.position[i].z, p.radius[i]);
    if (velocities) out << fmt::format(" 0.01 0 {:.17g}", -0.001 * double(i % 7));
    out << "\n";
  }
}

}  // namespace

// From a LAMMPS data file, then from a snapshot of that run: the pour is skipped, every particle
// is kept with its id, and both runs reach the end.
TEST(PackingStart, LammpsDataThenTheRunsSnapshot) {
  omp_set_num_threads(1);
  const ScratchDir scratch("trapdem-packing-data");
  const fs::path& dir = scratch.path();
  const Particles packed = lattice(4, 2600.0);
  write_lammps_data((dir / "bed.data").string(), packed, {0, 0, 0}, {0.08, 0.014, 0.045});

  const fs::path first = dir / "first";
  ASSERT_TRUE(run_folder(short_run((dir / "bed.data").string(), "lammps-data"), first));
  const auto snaps = list_snapshots(first / "snapshots.h5");
  ASSERT_GE(snaps.size(), 3u);
  EXPECT_EQ(snaps.front().stage, "packing");  // the packing as read is the first snapshot
  for (const SnapshotInfo& s : snaps) EXPECT_EQ(s.particle_count, packed.size()) << s.name;
  const Snapshot start = read_snapshot(first / "snapshots.h5", snaps.front().name);
  EXPECT_EQ(ids_of(start.id), ids_of(packed.id));
  const Snapshot end = read_snapshot(first / "snapshots.h5", snaps.back().name);
  EXPECT_EQ(ids_of(end.id), ids_of(packed.id));
  const Json record = Json::parse(read_text_file(first / "run.json"), "run.json");
  EXPECT_TRUE(record["complete"].as_bool());
  EXPECT_EQ(record["particles"].as_number(), double(packed.size()));
  // The file's density (2600, not the preset's 2500) is the particles' mass.
  const ExperimentConfig c = config_with(short_run((dir / "bed.data").string(), "lammps-data"));
  EXPECT_NEAR(c.packing.particles->density(0), 2600.0, 1e-9);
  const std::string log = read_text_file(first / "run.log");
  EXPECT_EQ(log.find("stage pluviation finished"), std::string::npos);
  EXPECT_NE(log.find("stage settling finished"), std::string::npos);

  // Snapshot 1 (the end of settling) of that run folder.
  std::vector<std::string> again = short_run(first.string(), "trapdem");
  again.push_back("packing.snapshot=1");
  ASSERT_EQ(snaps[1].stage, "settling");
  const fs::path second = dir / "second";
  ASSERT_TRUE(run_folder(again, second));
  const auto snaps2 = list_snapshots(second / "snapshots.h5");
  const Snapshot from = read_snapshot(first / "snapshots.h5", snaps[1].name);
  const Snapshot read_back = read_snapshot(second / "snapshots.h5", snaps2.front().name);
  EXPECT_EQ(read_back.id, from.id);
  EXPECT_EQ(read_back.position, from.position);  // no shift: the same places
  EXPECT_EQ(ids_of(read_snapshot(second / "snapshots.h5", snaps2.back().name).id), ids_of(packed.id));
}

// From a LAMMPS dump with velocities, shifted into the box, starting at spin-up.
TEST(PackingStart, DumpWithVelocitiesShiftedStartsAtSpinUp) {
  omp_set_num_threads(1);
  const ScratchDir scratch("trapdem-packing-dump");
  const fs::path& dir = scratch.path();
  Particles packed = lattice(3);
  for (Vec3& x : packed.position) x.z += 0.010;  // 10 mm too high: shift brings it down
  write_dump(dir / "bed.dump", packed, true);
  std::vector<std::string> o = short_run((dir / "bed.dump").string(), "lammps-dump");
  o.push_back("packing.shift=[0.0, 0.0, -0.0099]");
  o.push_back("packing.start_stage=spin_up");
  const ExperimentConfig c = config_with(o);
  ASSERT_EQ(c.packing.particles->size(), packed.size());
  EXPECT_NEAR(c.packing.particles->position[0].z, 0.0022 + 0.0001, 1e-12);
  EXPECT_EQ(c.packing.particles->velocity[1], (Vec3{0.01, 0.0, -0.001}));
  EXPECT_NEAR(c.packing.particles->density(0), 2500.0, 1e-9);  // no density column: [particles]

  TrapdoorExperiment experiment(c);
  EXPECT_EQ(experiment.stage(), Stage::spin_up);
  struct Stages : ExperimentObserver {
    std::vector<Stage> finished;
    void stage_finished(Stage s, const std::string&) override { finished.push_back(s); }
  } seen;
  ASSERT_TRUE(experiment.run(seen));
  EXPECT_EQ(seen.finished, (std::vector<Stage>{Stage::spin_up, Stage::lowering}));
  EXPECT_EQ(ids_of(experiment.simulation().particles().id), ids_of(packed.id));
}

// Each check's error names the file, the line and the particle id.
TEST(PackingStart, EachCheckNamesTheParticleAndLine) {
  const ScratchDir scratch("trapdem-packing-checks");
  const fs::path& dir = scratch.path();
  const fs::path dump = dir / "bad.dump";
  auto error_for = [&](Particles p, std::vector<std::string> extra = {}) {
    write_dump(dump, p, false);
    std::vector<std::string> o = short_run(dump.string(), "lammps-dump");
    o.insert(o.end(), extra.begin(), extra.end());
    return error_of(o);
  };
  // The dump's first atom line is line 10; atom k (0-based) is on line 10 + k.
  Particles p = lattice(1);
  p.position[0].x = 0.001;  // id 101, line 10: r = 2 mm reaches 1 mm into the left wall (allowed 0.5 mm)
  EXPECT_NE(error_for(p).find(fmt::format("{}:10: particle 101", dump.string())), std::string::npos) << error_for(p);
  EXPECT_NE(error_for(p).find("through the left wall"), std::string::npos);

  p = lattice(1);
  p.position[7].z = 0.0012;  // id 108, line 17: below the base
  EXPECT_NE(error_for(p).find(fmt::format("{}:17: particle 108", dump.string())), std::string::npos) << error_for(p);
  EXPECT_NE(error_for(p).find("below the base"), std::string::npos);
  // The same particle inside with a shift, and the shift alone can put it out.
  EXPECT_EQ(error_for(p, {"packing.shift=[0.0, 0.0, 0.001]"}), "(no error)");
  EXPECT_NE(error_for(lattice(1), {"packing.shift=[0.0, 0.0, 0.06]"}).find("above the box"), std::string::npos);

  p = lattice(1);
  p.position[11] = p.position[10] + Vec3{0.003, 0.0, 0.0};  // ids 111 and 112 overlap by 1 mm = 0.5 r
  EXPECT_NE(error_for(p).find(fmt::format("{}:20: particle 111", dump.string())), std::string::npos) << error_for(p);
  EXPECT_NE(error_for(p).find(fmt::format("overlaps particle 112 ({}:21)", dump.string())), std::string::npos);
  // Allowed by a larger max_overlap_fraction (the engine's overlap guard).
  EXPECT_EQ(error_for(p, {"numerics.max_overlap_fraction=0.6"}), "(no error)");

  p = lattice(1);
  p.radius[2] = -0.002;  // id 103, line 12
  EXPECT_NE(error_for(p).find(fmt::format("{}:12: the radius of atom 103 must be positive", dump.string())),
            std::string::npos) << error_for(p);

  // A LAMMPS data file: a zero diameter and an outside particle, with their Atoms lines.
  const fs::path data = dir / "bad.data";
  p = lattice(1);
  write_lammps_data(data.string(), p, {0, 0, 0}, {0.08, 0.014, 0.045});
  std::string text = read_text_file(data);
  const std::string line15 = fmt::format("106 1 {:.17g}", 0.004);
  ASSERT_NE(text.find(line15), std::string::npos);
  text.replace(text.find(line15), line15.size(), "106 1 0");
  std::ofstream(data) << text;
  const std::string zero = error_of(short_run(data.string(), "lammps-data"));
  EXPECT_NE(zero.find(data.string() + ":"), std::string::npos) << zero;
  EXPECT_NE(zero.find("diameter 0 of atom 106"), std::string::npos) << zero;
  p = lattice(1);
  p.position[1].y = 0.0135;  // id 102: through the front window; the Atoms lines start on line 12
  write_lammps_data(data.string(), p, {0, 0, 0}, {0.08, 0.014, 0.045});
  const std::string outside = error_of(short_run(data.string(), "lammps-data"));
  EXPECT_NE(outside.find(fmt::format("{}:13: particle 102", data.string())), std::string::npos) << outside;
  EXPECT_NE(outside.find("through the front window"), std::string::npos);

  // Bad format: a data file read as a dump, and a format that is not one.
  const std::string as_dump = error_of(short_run(data.string(), "lammps-dump"));
  EXPECT_NE(as_dump.find(data.string() + ":1: expected an 'ITEM:' line"), std::string::npos) << as_dump;
  EXPECT_NE(error_of(short_run(data.string(), "xyz")).find("packing.format = \"xyz\""), std::string::npos);
  // A device is no packing (it would be read without end).
  EXPECT_NE(error_of(short_run("/dev/zero", "lammps-data")).find("packing.from = \"/dev/zero\": not a regular file"),
            std::string::npos);
  // A snapshot index with a format that has none, and out of range of a run's snapshots.
  std::vector<std::string> o = short_run(data.string(), "lammps-data");
  o.push_back("packing.snapshot=0");
  EXPECT_NE(error_of(o).find("no snapshot index with this format"), std::string::npos) << error_of(o);
  const fs::path h5 = dir / "snapshots.h5";
  append_snapshot(h5, make_snapshot(lattice(1), 0.0, "settling", 0.0, 0));
  o = short_run(dir.string(), "trapdem");
  o.push_back("packing.snapshot=3");
  EXPECT_NE(error_of(o).find("packing.snapshot = 3, but the file holds 1 snapshot(s); expected 0 to 0"),
            std::string::npos) << error_of(o);
  // A trapdem snapshot's particle is named by its row.
  Particles q = lattice(1);
  q.position[5].x = -0.01;
  fs::remove(h5);
  fs::remove_all(dir / "snapshots");
  append_snapshot(h5, make_snapshot(q, 0.0, "settling", 0.0, 0));
  const std::string row = error_of(short_run(h5.string(), "trapdem"));
  EXPECT_NE(row.find(fmt::format("{} snapshot 000000, row 5: particle 106", h5.string())), std::string::npos) << row;
}

// A packing denser than a pour's (face-centred cubic at contact, solid fraction 0.74): the
// neighbour search lists every touching pair and the bed settles without tripping the overlap guard.
TEST(PackingStart, DensestPackingInTheNeighbourSearch) {
  omp_set_num_threads(1);
  const ScratchDir scratch("trapdem-packing-fcc");
  const fs::path& dir = scratch.path();
  const double r = 0.002, a = 4.0 * r / std::sqrt(2.0);  // FCC cell edge for spheres touching along face diagonals
  Particles p;
  std::int64_t id = 1;
  const Vec3 basis[4] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 13; ++i)
        for (const Vec3& b : basis) {
          const Vec3 x{(i + b.x) * a + r, (j + b.y) * a + r, (k + b.z) * a + r};
          if (x.x + r <= 0.08 && x.y + r <= 0.014 && x.z + r <= 0.045) p.add(id++, x, r, 2500.0);
        }
  write_lammps_data((dir / "fcc.data").string(), p, {0, 0, 0}, {0.08, 0.014, 0.045});
  const ExperimentConfig c = config_with(short_run((dir / "fcc.data").string(), "lammps-data"));
  TrapdoorExperiment experiment(c);
  Simulation& sim = experiment.simulation();
  sim.run(2000);
  const Particles& now = sim.particles();
  const PairList pairs = sim.pairs();
  std::set<std::pair<std::int64_t, std::int64_t>> listed;
  for (std::size_t i = 0; i + 1 < pairs.first.size(); ++i)
    for (std::uint32_t k = pairs.first[i]; k < pairs.first[i + 1]; ++k)
      listed.insert(std::minmax(now.id[i], now.id[pairs.partner[k]]));
  std::size_t touching = 0;
  for (std::size_t i = 0; i < now.size(); ++i)
    for (std::size_t j = i + 1; j < now.size(); ++j) {
      const Vec3 d = now.position[j] - now.position[i];
      if (dot(d, d) < std::pow(now.radius[i] + now.radius[j], 2)) {
        ++touching;
        EXPECT_TRUE(listed.count(std::minmax(now.id[i], now.id[j]))) << now.id[i] << "-" << now.id[j];
      }
    }
  // Most of the lattice's 12 neighbours per sphere (6 pairs each in the bulk) touch under gravity.
  EXPECT_GT(touching, 2 * now.size());
}

// The [packing] keys are part of the run's identity: a resume with another shift is refused, the
// same configuration carries on from the checkpoint (not from the file again) to the end.
TEST(PackingStart, ResumeIdentityCoversThePackingKeys) {
  omp_set_num_threads(1);
  const ScratchDir scratch("trapdem-packing-resume");
  const fs::path& dir = scratch.path();
  write_lammps_data((dir / "bed.data").string(), lattice(2), {0, 0, 0}, {0.08, 0.014, 0.045});
  FolderRunOptions o;
  o.config_file = kTiny;
  o.overrides = short_run((dir / "bed.data").string(), "lammps-data");
  o.out_dir = dir / "run";
  o.quiet = true;
  o.threads = 1;
  o.stop_at_step = 3000;
  ASSERT_FALSE(run_in_folder(o));
  // The folder's resolved.toml with another shift: the checkpoint's configuration differs.
  const fs::path resolved = dir / "run" / "resolved.toml";
  const std::string as_run = read_text_file(resolved);
  std::string edited = as_run;
  const std::string shift = "shift = [0.0, 0.0, 0.0]";
  ASSERT_NE(edited.find(shift), std::string::npos) << as_run;
  edited.replace(edited.find(shift), shift.size(), "shift = [0.0, 0.0, 0.001]");
  std::ofstream(resolved) << edited;
  FolderRunOptions resume;
  resume.resume_dir = o.out_dir;
  resume.quiet = true;
  resume.threads = 1;
  try {
    run_in_folder(resume);
    FAIL() << "expected the changed shift to be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("packing.shift was [0.0, 0.0, 0.0] at the checkpoint"), std::string::npos)
        << e.what();
  }
  std::ofstream(resolved) << as_run;
  ASSERT_TRUE(run_in_folder(resume));
  const auto snaps = list_snapshots(dir / "run" / "snapshots.h5");
  EXPECT_EQ(snaps.front().stage, "packing");
  EXPECT_EQ(std::count_if(snaps.begin(), snaps.end(), [](const SnapshotInfo& s) { return s.stage == "packing"; }), 1);
  EXPECT_EQ(snaps.back().particle_count, lattice(2).size());
}

// A dump's density column is the particles' density (else [particles].density, as above); a lone
// vx column is no velocity.
TEST(PackingStart, DumpDensityColumn) {
  const ScratchDir scratch("trapdem-packing-density");
  const fs::path& dir = scratch.path();
  std::ofstream(dir / "bed.dump") << "ITEM: TIMESTEP\n0\nITEM: NUMBER OF ATOMS\n2\nITEM: ATOMS id x y z radius density vx\n"
                                     "4 0.02 0.007 0.0022 0.002 3000 5\n9 0.03 0.007 0.0022 0.002 2000 5\n";
  const ExperimentConfig c = config_with(short_run((dir / "bed.dump").string(), "lammps-dump"));
  ASSERT_EQ(c.packing.particles->size(), 2u);
  EXPECT_NEAR(c.packing.particles->density(0), 3000.0, 1e-9);
  EXPECT_NEAR(c.packing.particles->density(1), 2000.0, 1e-9);
  EXPECT_EQ(c.packing.particles->velocity[0], Vec3{});
  EXPECT_EQ(c.packing.particles->id, (std::vector<std::int64_t>{4, 9}));
}

namespace {

// While alive, the process works in `folder` (then in the folder it was in before).
class WorkingFolder {
 public:
  explicit WorkingFolder(const fs::path& folder) : before_(fs::current_path()) { fs::current_path(folder); }
  ~WorkingFolder() { fs::current_path(before_); }
  WorkingFolder(const WorkingFolder&) = delete;
  WorkingFolder& operator=(const WorkingFolder&) = delete;

 private:
  fs::path before_;
};

}  // namespace

// A relative packing.from in a configuration file names a file beside that file (as an #include),
// whatever the working folder; given with --set it names one in the working folder. The working
// folder holds another packing of the same name, so that taking the wrong folder shows in the
// particle count. The resolved configuration names the file absolute: read again from elsewhere
// (as a resume reads the run folder's resolved.toml) it is the same file.
TEST(PackingStart, RelativeFromIsTheConfigurationFilesFolder) {
  const ScratchDir scratch("trapdem-packing-relative");
  const fs::path& dir = scratch.path();
  for (const char* sub : {"configs", "work", "run"}) fs::create_directories(dir / sub);
  const Particles beside = lattice(2), in_work = lattice(1);
  write_dump(dir / "configs" / "bed.dump", beside, false);
  write_dump(dir / "work" / "bed.dump", in_work, false);
  std::ofstream(dir / "configs" / "run.toml") << read_text_file(kTiny)
                                               << "\n[packing]\nfrom = \"bed.dump\"\nformat = \"lammps-dump\"\n";
  const std::string absolute = (dir / "configs" / "bed.dump").lexically_normal().string();
  std::string resolved;
  {
    const WorkingFolder work(dir / "work");
    Config file = Config::load_file("../configs/run.toml");
    const ExperimentConfig c = ExperimentConfig::from(file);
    EXPECT_EQ(c.packing.from, absolute);
    EXPECT_EQ(c.packing.particles->size(), beside.size());
    resolved = file.resolved_toml();
    EXPECT_NE(resolved.find("from = \"" + absolute + "\""), std::string::npos) << resolved;

    Config set = Config::load_file("../configs/run.toml");
    set.apply_override("packing.from=\"bed.dump\"");
    const ExperimentConfig s = ExperimentConfig::from(set);
    EXPECT_EQ(s.packing.from, (dir / "work" / "bed.dump").lexically_normal().string());
    EXPECT_EQ(s.packing.particles->size(), in_work.size());
  }
  std::ofstream(dir / "run" / "resolved.toml") << resolved;
  const WorkingFolder elsewhere(dir);
  Config again = Config::load_file((dir / "run" / "resolved.toml").string());
  EXPECT_EQ(ExperimentConfig::from(again).packing.particles->size(), beside.size());
}

// docs/output.md's example as written (issue 41): the tiny preset's own settled deposit (snapshot 1
// of a whole tiny pour and settling) starts a tiny run. The settling's line in run.log measures the
// deposit's surface and its highest top, which stay inside the box; in a box lower than the
// deposit the same line says how many particles stand above it and what box a run from it needs.
TEST(PackingStart, TheDocsExampleStartsFromTheTinyPresetsOwnDeposit) {
  omp_set_num_threads(1);
  const ScratchDir scratch("trapdem-packing-docs-example");
  const fs::path dir = scratch.path();
  FolderRunOptions poured;
  poured.config_file = kTiny;
  poured.overrides = {"spin_up.ramp_time=0.005", "trapdoor.travel=0.0005", "output.snapshot_displacements=[0.0]"};
  poured.out_dir = dir / "tiny";
  poured.quiet = true;
  poured.threads = 1;
  ASSERT_TRUE(run_in_folder(poured));
  const std::string log = read_text_file(dir / "tiny" / "run.log");
  const auto settled = log.find("stage settling finished");
  ASSERT_NE(settled, std::string::npos) << log;
  const std::string line = log.substr(settled, log.find('\n', settled) - settled);
  EXPECT_NE(line.find("deposit surface at "), std::string::npos) << line;
  EXPECT_EQ(line.find("above the box"), std::string::npos) << line;
  const auto snaps = read_snapshots(dir / "tiny" / "snapshots.h5");
  double highest = 0.0;
  for (std::size_t i = 0; i < snaps[1].size(); ++i)
    highest = std::max(highest, snaps[1].position[i].z + snaps[1].radius[i]);
  EXPECT_LT(highest, config_with({}).box.height);

  FolderRunOptions from_deposit = poured;
  from_deposit.overrides = {"packing.from=" + (dir / "tiny").string(), "packing.format=trapdem", "packing.snapshot=1",
                            "spin_up.ramp_time=0.005", "trapdoor.travel=0.0005", "output.snapshot_displacements=[0.0]"};
  from_deposit.out_dir = dir / "from-deposit";
  ASSERT_TRUE(run_in_folder(from_deposit));

  // The same pour in a box 15 mm lower: said where the deposit is measured.
  FolderRunOptions low = poured;
  low.overrides.push_back("box.height=0.045");
  low.out_dir = dir / "low";
  ASSERT_TRUE(run_in_folder(low));
  const std::string low_log = read_text_file(dir / "low" / "run.log");
  EXPECT_NE(low_log.find("stand above the box's height (45.0 mm): a run started from this deposit needs box.height >="),
            std::string::npos)
      << low_log;
}

// A run of dimers (particles.shape) whose settled snapshot starts another run of the same dimers
// (issue 39): every clump rebuilt at its centre of mass and orientation, its members where the
// snapshot has them (to 1e-12 m: the engine places members by a rotation matrix, the packing by
// the quaternion, two roundings of ~1e-17 m), the second run complete with the same bodies. A
// configuration of another shape or of spheres is refused naming the body or the snapshot, and so
// is a clump configuration with a file of spheres.
TEST(PackingStart, AClumpRunsSnapshotStartsARunOfTheSameClumps) {
  omp_set_num_threads(1);
  const ScratchDir scratch("trapdem-packing-clumps");
  const fs::path& dir = scratch.path();
  const std::vector<std::string> dimers = {"particles.shape.kind=\"dimer\"", "particles.shape.aspect=1.5"};
  std::vector<std::string> pour = {"pluviation.fill_height=0.02", "settling.max_time=0.02", "spin_up.ramp_time=0.005",
                                   "trapdoor.travel=0.0005", "output.snapshot_displacements=[0.0]"};
  pour.insert(pour.end(), dimers.begin(), dimers.end());
  const fs::path first = dir / "first";
  ASSERT_TRUE(run_folder(pour, first));
  const auto snaps = list_snapshots(first / "snapshots.h5");
  ASSERT_GE(snaps.size(), 2u);
  ASSERT_EQ(snaps[1].stage, "settling");
  const Snapshot settled = read_snapshot(first / "snapshots.h5", snaps[1].name);
  ASSERT_FALSE(settled.bodies.empty());

  std::vector<std::string> again = short_run(first.string(), "trapdem");
  again.push_back("packing.snapshot=1");
  std::vector<std::string> again_dimers = again;
  again_dimers.insert(again_dimers.end(), dimers.begin(), dimers.end());
  const ExperimentConfig c = config_with(again_dimers);
  ASSERT_TRUE(c.packing.bodies);
  const RigidBodies& bodies = *c.packing.bodies;
  const Particles& members = *c.packing.particles;
  ASSERT_EQ(bodies.size(), settled.bodies.size());
  ASSERT_EQ(members.size(), settled.size());
  std::map<std::int64_t, std::size_t> row_of_body;
  for (std::size_t k = 0; k < settled.bodies.size(); ++k) row_of_body[settled.bodies.id[k]] = k;
  double worst = 0.0;
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const std::size_t k = row_of_body.at(bodies.id[b]);
    EXPECT_EQ(bodies.position[b], settled.bodies.position[k]);
    EXPECT_EQ(bodies.velocity[b], settled.bodies.velocity[k]);
    // Each member at one of the snapshot's members of that body.
    for (std::uint32_t m = bodies.first_member[b]; m < bodies.first_member[b + 1]; ++m) {
      double nearest = 1.0;
      for (std::size_t i = 0; i < settled.size(); ++i)
        if (settled.body[i] == bodies.id[b])
          nearest = std::min(nearest, norm(members.position[bodies.member_particle[m]] - settled.position[i]));
      worst = std::max(worst, nearest);
    }
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_GT(c.packing.critical_time_step, 0.0);
  EXPECT_NEAR(c.material.sizes.mean_diameter(), 0.004, 0.0005) << "the grains' volume-equivalent sizes";

  const fs::path second = dir / "second";
  ASSERT_TRUE(run_folder(again_dimers, second));
  const auto snaps2 = list_snapshots(second / "snapshots.h5");
  const Snapshot start = read_snapshot(second / "snapshots.h5", snaps2.front().name);
  EXPECT_EQ(snaps2.front().stage, "packing");
  EXPECT_EQ(ids_of(start.bodies.id), ids_of(settled.bodies.id));
  EXPECT_TRUE(Json::parse(read_text_file(second / "run.json"), "run.json")["complete"].as_bool());

  std::vector<std::string> other_shape = again;
  other_shape.insert(other_shape.end(), {"particles.shape.kind=\"dimer\"", "particles.shape.aspect=1.2"});
  const std::string wrong = error_of(other_shape);
  EXPECT_NE(wrong.find("snapshot 000001, body "), std::string::npos) << wrong;
  EXPECT_NE(wrong.find("must be of the configuration's shape"), std::string::npos) << wrong;
  const std::string spheres = error_of(again);
  EXPECT_NE(spheres.find(fmt::format("a snapshot of {} clumps", settled.bodies.size())), std::string::npos) << spheres;
  EXPECT_NE(spheres.find("[particles.shape]"), std::string::npos) << spheres;

  write_lammps_data((dir / "bed.data").string(), lattice(2), {0, 0, 0}, {0.08, 0.014, 0.045});
  std::vector<std::string> data = short_run((dir / "bed.data").string(), "lammps-data");
  data.insert(data.end(), dimers.begin(), dimers.end());
  const std::string from_data = error_of(data);
  EXPECT_NE(from_data.find("a packing of clumps is a trapdem snapshot of clumps"), std::string::npos) << from_data;
}
