#include "study/element_folder.hpp"

#include <omp.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "dem/thread_scope.hpp"
#include "experiment/element_config.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "plot/element_figure.hpp"

namespace trapdem {

namespace fs = std::filesystem;

namespace {

plot::ElementCurve curve_of(const SpecimenResult& s, std::size_t pressure_index) {
  plot::ElementCurve c;
  c.name = fmt::format("{}, {:.4g} kPa", to_string(s.packing), s.confining / 1e3);
  for (const ElementRow& r : s.rows) {
    c.axial_strain.push_back(r.axial_strain);
    c.sin_phi.push_back(r.sin_phi);
    c.volumetric_strain.push_back(r.volumetric_strain);
  }
  c.colour = plot::series_colour(pressure_index);
  c.dashed = s.packing == Packing::loose;
  return c;
}

}  // namespace

ElementFolderResult run_element_in_folder(const ElementFolderOptions& o) {
  Config config = Config::load_file(o.config_file.string());
  config.apply_overrides(o.overrides);
  const ElementSetup setup = read_element_setup(config);

  ElementFolderResult done;
  done.out = o.out_dir.empty() ? fs::path("trapdem-out") / ("element-" + setup.name) : o.out_dir;
  std::error_code ec;
  fs::create_directories(done.out, ec);
  if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", done.out.string(), ec.message()));
  write_text_atomically(done.out / "resolved.toml", config.resolved_toml());
  const ThreadScope threads(o.threads > 0 ? o.threads : setup.threads);

  std::ofstream log_file(done.out / "element.log");
  if (!log_file) throw FileError(fmt::format("cannot open {} for writing", (done.out / "element.log").string()));
  const ElementLog log = [&](const std::string& line) {
    if (o.echo) o.echo(line);
    log_file << line << '\n';
    log_file.flush();
  };
  const ElementSettings& e = setup.settings;
  log(fmt::format("element test ({}) of {}: {} particles of {:.3g} mm mean diameter, time step {:.3g} s, I = {:.2g}, "
                  "to {:.0f} % axial strain, {} threads",
                  to_string(e.kind), setup.name, e.particles, setup.material.sizes.mean_diameter() * 1e3,
                  setup.time_step, e.inertial_number, 100.0 * e.max_axial_strain, omp_get_max_threads()));

  done.result = run_element_test(setup, log);
  write_element_files(done.out, done.result);

  std::vector<plot::ElementCurve> curves;
  for (const SpecimenResult& s : done.result.specimens) {
    std::size_t index = 0;
    while (index < e.confining.size() && e.confining[index] != s.confining) ++index;
    curves.push_back(curve_of(s, index));
  }
  // Table 1's glass beads: phi'_cs 15.7 deg and phi'_peak 16.8 deg as reference lines.
  const double to_rad = std::numbers::pi / 180.0;
  plot::write_element_figure(
      done.out / "element.png", fmt::format("{} test: {}", to_string(e.kind), setup.name),
      fmt::format("{} particles, I = {:.2g}; dotted: glass beads (seed Table 1) phi' 15.7 and 16.8 deg", e.particles,
                  e.inertial_number),
      curves, {std::sin(15.7 * to_rad), std::sin(16.8 * to_rad)});

  // "cs inside": phi'_cs from the contact stress of the interior (element.interior_margin inside
  // every wall), without the walls' layers (docs/element.md).
  log(fmt::format("{:>14} {:>12} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}", "confining", "packing", "solid fr.",
                  "phi'_peak", "phi'_cs", "cs inside", "psi_peak", "LW/wall"));
  for (const SpecimenResult& s : done.result.specimens)
    log(fmt::format("{:>10.4g} kPa {:>12} {:>10.4f} {:>10.1f} {:>10.1f} {:>10.1f} {:>10.1f} {:>10.4f}", s.confining / 1e3,
                    to_string(s.packing), s.isotropic.solid_fraction, s.phi_peak, s.phi_cs, s.phi_cs_interior,
                    s.psi_peak, s.isotropic.love_weber_mean() / s.isotropic.wall_mean()));
  done.angles = element_angles(done.result);
  for (const ElementAngles& a : done.angles)
    log(fmt::format("at {:.4g} kPa: phi'_peak {:.1f} deg, phi'_cs {:.1f} deg (dense and loose {:.1f} deg apart)",
                    a.confining / 1e3, a.phi_peak, a.phi_cs, a.phi_cs_gap));
  log(fmt::format("wrote {}", (done.out / "element.json").string()));
  return done;
}

}  // namespace trapdem
