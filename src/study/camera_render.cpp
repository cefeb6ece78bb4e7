#include "study/camera_render.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "experiment/run_folder.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot.hpp"
#include "piv/png_file.hpp"
#include "piv/run_piv.hpp"
#include "study/run_analysis.hpp"

namespace trapdem {

namespace fs = std::filesystem;

CameraRender render_run_snapshots(const CameraRenderOptions& o) {
  const RunFolder run(o.run);
  const SpecimenGeometry g = load_specimen_geometry(o.config.empty() ? run.resolved_toml() : o.config);
  const fs::path h5 = run.snapshots_h5();
  if (!fs::exists(h5)) throw InputError(fmt::format("{}: not found (run `trapdem run` first)", h5.string()));
  CameraRender r;
  r.snapshots = read_snapshots(h5);
  if (r.snapshots.empty()) throw InputError(fmt::format("{}: no snapshots", h5.string()));
  r.px_per_mm = o.px_per_mm;
  r.camera.front_wall_y = g.box_depth;
  r.view = camera_view_for(r.snapshots, g.box_width, o.px_per_mm, r.camera);
  r.out = o.out.empty() ? run.camera_dir() : o.out;
  std::error_code ec;
  fs::create_directories(r.out, ec);
  if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", r.out.string(), ec.message()));
  for (std::size_t k = 0; k < r.snapshots.size(); ++k) {
    const fs::path path = r.out / fmt::format("{:03d}_{:g}mm.png", k,
                                              std::round(r.snapshots[k].trapdoor_displacement * 1e4) / 10.0 + 0.0);
    write_png_atomically(path, render_front_view(r.snapshots[k], r.view, r.camera));
    r.images.push_back(path);
  }
  // PIV from the start of lowering: the images before it (pour, settling, spin-up) are not listed.
  std::vector<double> displacements;
  for (const Snapshot& s : r.snapshots) displacements.push_back(s.trapdoor_displacement);
  r.lowering_starts_at = lowering_start(displacements);
  std::string listed;
  for (std::size_t k = r.lowering_starts_at; k < r.images.size(); ++k) listed += r.images[k].string() + " ";
  r.piv_command = fmt::format("trapdem piv {}--out {}/piv --scale {:g} --origin {:g},{:g}", listed, r.out.string(),
                              r.view.mm_per_px, r.view.origin_x_mm, r.view.origin_z_mm);
  const std::string first = r.images[r.lowering_starts_at].filename().string();
  write_text_atomically(
      r.out / "scale.txt",
      fmt::format("# trapdem render: orthographic view through the front window (y = {:g} mm), particles with centres\n"
                  "# within one diameter of it. Pixel (col, row) has its centre at image (x, y) = (col, row), x right,\n"
                  "# y down; model x = origin_x_mm + mm_per_px * x, z (up) = origin_z_mm - mm_per_px * y.\n"
                  "mm_per_px = {:g}\norigin_x_mm = {:g}\norigin_z_mm = {:g}\nwidth_px = {}\nheight_px = {}\n"
                  "lowering_starts_at = {}\n"
                  "# PIV with the model coordinates, from the start of lowering (image {} of {}, {}):\n# {}\n",
                  g.box_depth * 1e3, r.view.mm_per_px, r.view.origin_x_mm, r.view.origin_z_mm, r.view.width,
                  r.view.height, first, r.lowering_starts_at + 1, r.images.size(), first, r.piv_command));
  return r;
}

CameraCheck check_rendered_piv(const CameraRender& r, int subset, int threads) {
  CameraCheck check;
  if (r.snapshots.size() < 2) return check;
  PivSettings s;
  const double mean_diameter_px = 2.0 * r.snapshots[0].radius[0] * 1e3 * r.px_per_mm;
  s.subset_size = subset > 0 ? subset : std::max(16, static_cast<int>(std::round(3.0 * mean_diameter_px / 2.0)) * 2);
  s.step = s.subset_size / 2;
  s.threads = threads;
  check.subset = s.subset_size;
  check.step = s.step;
  // Reference: the start of lowering (the analysis' 0 mm), as the suggested PIV.
  const std::size_t first = r.lowering_starts_at;
  const std::vector<fs::path> paths(r.images.begin() + static_cast<std::ptrdiff_t>(first), r.images.end());
  if (paths.size() < 2) return check;
  const PivResult piv = run_piv(paths, s);
  for (std::size_t k = 1; k < piv.image_count(); ++k)
    check.rows.push_back({r.snapshots[first + k].trapdoor_displacement,
                          compare_with_particles(piv, k, r.snapshots[first], r.snapshots[first + k], r.view, r.camera)});
  return check;
}

}  // namespace trapdem
