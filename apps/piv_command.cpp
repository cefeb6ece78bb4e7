#include "piv_command.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "core/number_list.hpp"
#include "piv/piv_folder.hpp"
#include "piv/synthetic_sequence.hpp"
#include "plot/figure_format.hpp"
#include "study/camera_render.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

int run_piv_command(const PivOptions& o) {
  if (o.images.size() < 2) throw InputError("trapdem piv: give at least two images, in order");
  if (o.out.empty()) throw InputError("trapdem piv: --out DIR is required");
  if (o.scale && !o.control_points.empty()) throw InputError("--scale and --control-points exclude each other");
  if (!o.origin.empty() && !o.scale) throw InputError("--origin goes with --scale");
  PivFolderOptions f;
  f.images.assign(o.images.begin(), o.images.end());
  f.out = o.out;
  f.settings.subset_size = o.subset;
  f.settings.step = o.step;
  f.settings.threads = o.threads;
  if (!o.roi.empty()) {
    const auto v = parse_number_list(o.roi, 4, "--roi");
    for (double x : v) {
      if (x != std::floor(x)) throw InputError(fmt::format("--roi '{}': whole pixels expected", o.roi));
    }
    if (!(v[2] > v[0] && v[3] > v[1])) {
      throw InputError(fmt::format("--roi '{}' is empty: x1 must exceed x0 and y1 exceed y0", o.roi));
    }
    f.settings.roi = RegionOfInterest{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]),
                                      static_cast<int>(v[3])};
  }
  if (o.scale) {
    if (!(*o.scale > 0.0)) throw InputError("--scale must be positive (mm per px)");
    f.scale_mm_per_px = *o.scale;
    if (!o.origin.empty()) {
      const auto v = parse_number_list(o.origin, 2, "--origin");
      f.origin_mm = {v[0], v[1]};
    }
  } else if (!o.control_points.empty()) {
    if (o.fit != "affine" && o.fit != "projective") throw InputError("--fit: affine or projective");
    f.control_points = o.control_points;
    f.fit = o.fit == "affine" ? ControlPointFitKind::affine : ControlPointFitKind::projective;
  }
  f.figures = !o.no_figures;
  f.format = plot::parse_figure_format(o.format, "--format");
  if (!o.contour_levels.empty() && !o.contour_step.empty()) {
    throw InputError("--contour-levels and --contour-step exclude each other");
  }
  if (!o.contour_levels.empty()) {
    const auto count = static_cast<std::size_t>(std::count(o.contour_levels.begin(), o.contour_levels.end(), ',')) + 1;
    f.settlement_levels.list = parse_number_list(o.contour_levels, count, "--contour-levels");
  }
  if (!o.contour_step.empty()) {
    f.settlement_levels.step = parse_number_list(o.contour_step, 1, "--contour-step")[0];
    if (!(f.settlement_levels.step > 0.0)) throw InputError("--contour-step must be positive");
  }
  const PivFolderResult r = run_piv_into_folder(f, [&](std::size_t k, const ImageMeasurements& m) {
    if (o.quiet) return;
    if (k == 0) {
      fmt::print("{} subsets of {} px every {} px on image 1 ({})\n", m.subset.size(), f.settings.subset_size,
                 f.settings.step, o.images[0]);
      return;
    }
    std::size_t valid = 0;
    for (const auto& x : m.subset) valid += x.is_valid();
    fmt::print("image {:>3}/{} {}: {:.2f} s, {:.1f} % valid, reference image {}{}\n", k + 1, o.images.size(),
               fs::path(o.images[k]).filename().string(), m.seconds,
               100.0 * static_cast<double>(valid) / std::max<std::size_t>(1, m.subset.size()), m.reference + 1,
               m.attempts > 1 ? " (reference updated)" : "");
    std::fflush(stdout);
  });
  if (o.quiet) return 0;
  if (r.fit) {
    fmt::print("control points: {} fit of {} points, residual RMS {:.4g}, max {:.4g} (model units)\n", o.fit,
               r.control_points.size(), r.fit->rms_residual, r.fit->max_residual);
    for (std::size_t i = 0; i < r.control_points.size(); ++i) {
      fmt::print("  point {}: ({:.1f}, {:.1f}) px -> residual {:.4g}\n", i + 1, r.control_points[i].pixel.x,
                 r.control_points[i].pixel.y, r.fit->residual[i]);
    }
  }
  double matching = 0.0;
  for (std::size_t k = 1; k < r.result.image_count(); ++k) matching += r.result.image[k].seconds;
  fmt::print("{} image pairs in {:.1f} s ({:.0f} subsets per second over the pairs); references used:",
             r.result.image_count() - 1, r.seconds,
             matching > 0 ? static_cast<double>(r.subsets * (r.result.image_count() - 1)) / matching : 0.0);
  for (auto ref : r.result.reference_images) fmt::print(" {}", ref + 1);
  fmt::print("\n  written: ");
  for (std::size_t k = 0; k < r.written.size(); ++k) fmt::print("{}{}", k ? ", " : "", r.written[k].filename().string());
  fmt::print(" in {}\n", o.out);
  return 0;
}

int run_synth_command(const SynthOptions& o) {
  if (o.out.empty()) throw InputError("trapdem synth: --out DIR is required");
  SyntheticSequenceOptions s;
  {
    const auto x = o.size.find('x');
    try {
      if (x == std::string::npos) throw std::invalid_argument(o.size);
      s.width = std::stoi(o.size.substr(0, x));
      s.height = std::stoi(o.size.substr(x + 1));
    } catch (const std::exception&) {
      throw InputError(fmt::format("--size '{}': expected WIDTHxHEIGHT in px, e.g. 512x512", o.size));
    }
  }
  s.field = parse_synthetic_field(o.field, "--field");
  s.out = o.out;
  s.images = o.images;
  s.noise = o.noise;
  s.magnitude = o.magnitude;
  s.seed = o.seed;
  const SyntheticSequence written = write_synthetic_sequence(s);
  fmt::print("{} speckle images {}x{} px ({} field, last image magnitude {:g}{}, noise {:g} grey levels) and truth.csv in {}\n",
             written.images, s.width, s.height, o.field, written.magnitude,
             (o.field == "strain" || o.field == "shear") ? "" : " px", o.noise, o.out);
  return 0;
}

int run_render_command(const RenderOptions& o) {
  CameraRenderOptions c;
  c.run = o.dir;
  c.out = o.out;
  c.px_per_mm = o.px_per_mm;
  c.config = o.config;
  const CameraRender r = render_run_snapshots(c);
  fmt::print("{} images {}x{} px at {:g} px/mm in {} (scale.txt: pixel (0,0) is model ({:g}, {:g}) mm)\n  PIV: {}\n",
             r.images.size(), r.view.width, r.view.height, o.px_per_mm, r.out.string(), r.view.origin_x_mm,
             r.view.origin_z_mm, r.piv_command);
  if (o.check && r.snapshots.size() >= 2) {
    const CameraCheck check = check_rendered_piv(r, o.subset, o.threads);
    if (check.rows.empty()) {
      fmt::print("check: no snapshot after the trapdoor started to move\n");
      return 0;
    }
    fmt::print("check: PIV ({} px subsets, step {} px) from {} against the front-layer particles' mean displacement "
               "per subset\n",
               check.subset, check.step, r.images[r.lowering_starts_at].filename().string());
    for (const CameraCheckRow& row : check.rows) {
      const CameraAgreement& a = row.agreement;
      const double delta_mm = row.trapdoor_displacement * 1e3;
      fmt::print("  {:g} mm: {} subsets, RMS vertical error {:.3f} px = {:.3f} mm = {:.2f} % of the trapdoor "
                 "displacement (bias {:+.3f} px), RMS vector error {:.3f} px, largest displacement {:.1f} px\n",
                 delta_mm, a.subsets, a.rms_vertical_error_px, a.rms_vertical_error_mm,
                 delta_mm > 0 ? 100.0 * a.rms_vertical_error_mm / delta_mm : 0.0, a.mean_vertical_error_px,
                 a.rms_error_px, a.max_particle_displacement_px);
    }
  }
  return 0;
}

}  // namespace trapdem::app
