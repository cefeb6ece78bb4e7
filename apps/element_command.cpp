#include "element_command.hpp"

#include <omp.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "experiment/element_config.hpp"
#include "experiment/element_output.hpp"
#include "experiment/element_test.hpp"
#include "io/atomic_file.hpp"
#include "io/config.hpp"
#include "core/errors.hpp"
#include "plot/element_figure.hpp"
#include "run_command.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

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

int run_element(const ElementOptions& o) {
  if (!o.config_file.empty() && !o.preset.empty()) throw InputError("give either a configuration file or --preset, not both");
  const std::string file = !o.config_file.empty() ? o.config_file : preset_path(o.preset.empty() ? "demo" : o.preset).string();
  Config config = Config::load_file(file);
  // The options go through the configuration as overrides, so that they are checked and recorded
  // (resolved.toml) as the file's own keys are.
  std::vector<std::string> overrides;
  if (!o.test.empty()) overrides.push_back("element.test=" + o.test);
  if (!o.confining.empty()) {
    std::string list;
    for (double p : o.confining) list += fmt::format("{}{}", list.empty() ? "" : ", ", p);
    overrides.push_back("element.confining=[" + list + "]");
  }
  overrides.insert(overrides.end(), o.overrides.begin(), o.overrides.end());
  config.apply_overrides(overrides);
  const ElementSetup setup = read_element_setup(config);

  const fs::path out = o.out_dir.empty() ? fs::path("trapdem-out") / ("element-" + setup.name) : fs::path(o.out_dir);
  std::error_code ec;
  fs::create_directories(out, ec);
  if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", out.string(), ec.message()));
  write_text_atomically(out / "resolved.toml", config.resolved_toml());
  const int threads = o.threads > 0 ? o.threads : setup.threads;
  if (threads > 0) omp_set_num_threads(threads);

  std::ofstream log_file(out / "element.log");
  if (!log_file) throw FileError(fmt::format("cannot open {} for writing", (out / "element.log").string()));
  const ElementLog log = [&](const std::string& line) {
    if (!o.quiet) {
      fmt::print("{}\n", line);
      std::fflush(stdout);
    }
    log_file << line << '\n';
    log_file.flush();
  };
  const ElementSettings& e = setup.settings;
  log(fmt::format("element test ({}) of {}: {} particles of {:.3g} mm mean diameter, time step {:.3g} s, I = {:.2g}, "
                  "to {:.0f} % axial strain, {} threads",
                  to_string(e.kind), setup.name, e.particles, setup.material.sizes.mean_diameter() * 1e3,
                  setup.time_step, e.inertial_number, 100.0 * e.max_axial_strain, omp_get_max_threads()));

  const ElementResult result = run_element_test(setup, log);
  write_element_files(out, result);

  std::vector<plot::ElementCurve> curves;
  for (const SpecimenResult& s : result.specimens) {
    std::size_t index = 0;
    while (index < e.confining.size() && e.confining[index] != s.confining) ++index;
    curves.push_back(curve_of(s, index));
  }
  // Table 1's glass beads: phi'_cs 15.7 deg and phi'_peak 16.8 deg as reference lines.
  const double to_rad = std::numbers::pi / 180.0;
  plot::write_element_figure(
      out / "element.png", fmt::format("{} test: {}", to_string(e.kind), setup.name),
      fmt::format("{} particles, I = {:.2g}; dotted: glass beads (seed Table 1) phi' 15.7 and 16.8 deg", e.particles,
                  e.inertial_number),
      curves, {std::sin(15.7 * to_rad), std::sin(16.8 * to_rad)});

  // "cs inside": phi'_cs from the contact stress of the interior (element.interior_margin inside
  // every wall), without the walls' layers (docs/element.md).
  log(fmt::format("{:>14} {:>8} {:>10} {:>10} {:>10} {:>10} {:>10} {:>10}", "confining", "packing", "solid fr.",
                  "phi'_peak", "phi'_cs", "cs inside", "psi_peak", "LW/wall"));
  for (const SpecimenResult& s : result.specimens)
    log(fmt::format("{:>10.4g} kPa {:>8} {:>10.4f} {:>10.1f} {:>10.1f} {:>10.1f} {:>10.1f} {:>10.4f}", s.confining / 1e3,
                    to_string(s.packing), s.isotropic.solid_fraction, s.phi_peak, s.phi_cs, s.phi_cs_interior,
                    s.psi_peak, s.isotropic.love_weber_mean() / s.isotropic.wall_mean()));
  for (const ElementAngles& a : element_angles(result))
    log(fmt::format("at {:.4g} kPa: phi'_peak {:.1f} deg, phi'_cs {:.1f} deg (dense and loose {:.1f} deg apart)",
                    a.confining / 1e3, a.phi_peak, a.phi_cs, a.phi_cs_gap));
  log(fmt::format("wrote {}", (out / "element.json").string()));
  return 0;
}

}  // namespace trapdem::app
