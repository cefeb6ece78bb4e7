#include "piv_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "core/errors.hpp"
#include "core/number_list.hpp"
#include "experiment/run_folder.hpp"
#include "io/atomic_file.hpp"
#include "io/snapshot.hpp"
#include "piv/control_point_file.hpp"
#include "piv/dem_camera.hpp"
#include "piv/displacement_csv.hpp"
#include "piv/piv_output.hpp"
#include "piv/run_piv.hpp"
#include "piv/speckle_synthesis.hpp"
#include "plot/figure_format.hpp"
#include "study/run_analysis.hpp"

namespace fs = std::filesystem;

namespace trapdem::app {

namespace {

std::string image_label(const std::vector<std::string>& images) {
  if (images.empty()) return "PIV";
  return fmt::format("PIV {} … {}", fs::path(images.front()).filename().string(),
                     fs::path(images.back()).filename().string());
}

cv::Mat read_for_figure(const std::string& file) {
  const cv::Mat m = cv::imread(file, cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR);
  if (m.empty()) throw InputError(fmt::format("{}: cannot be read as an image", file));
  return to_grey8(m);
}

}  // namespace

int run_piv_command(const PivOptions& o) {
  if (o.images.size() < 2) throw InputError("trapdem piv: give at least two images, in order");
  if (o.out.empty()) throw InputError("trapdem piv: --out DIR is required");
  if (o.scale && !o.control_points.empty()) throw InputError("--scale and --control-points exclude each other");
  if (!o.origin.empty() && !o.scale) throw InputError("--origin goes with --scale");
  PivSettings s;
  s.subset_size = o.subset;
  s.step = o.step;
  s.threads = o.threads;
  if (!o.roi.empty()) {
    const auto v = parse_number_list(o.roi, 4, "--roi");
    for (double x : v) {
      if (x != std::floor(x)) throw InputError(fmt::format("--roi '{}': whole pixels expected", o.roi));
    }
    if (!(v[2] > v[0] && v[3] > v[1])) {
      throw InputError(fmt::format("--roi '{}' is empty: x1 must exceed x0 and y1 exceed y0", o.roi));
    }
    s.roi = RegionOfInterest{static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2]),
                             static_cast<int>(v[3])};
  }
  std::optional<PixelToModel> model;
  std::string unit = "px";
  if (o.scale) {
    cv::Point2d origin_px{0.0, 0.0};
    if (!o.origin.empty()) {
      const auto v = parse_number_list(o.origin, 2, "--origin");
      origin_px = {-v[0] / *o.scale, v[1] / *o.scale};
    }
    if (!(*o.scale > 0.0)) throw InputError("--scale must be positive (mm per px)");
    model = scale_transform(*o.scale, origin_px);
    unit = "mm";
  } else if (!o.control_points.empty()) {
    if (o.fit != "affine" && o.fit != "projective") throw InputError("--fit: affine or projective");
    const auto points = read_control_points(o.control_points);
    const ControlPointFit fit = fit_control_points(
        points, o.fit == "affine" ? ControlPointFitKind::affine : ControlPointFitKind::projective);
    model = fit.transform;
    unit = "model units";
    if (!o.quiet) {
      fmt::print("control points: {} fit of {} points, residual RMS {:.4g}, max {:.4g} (model units)\n", o.fit,
                 points.size(), fit.rms_residual, fit.max_residual);
      for (std::size_t i = 0; i < points.size(); ++i) {
        fmt::print("  point {}: ({:.1f}, {:.1f}) px -> residual {:.4g}\n", i + 1, points[i].pixel.x,
                   points[i].pixel.y, fit.residual[i]);
      }
    }
  }
  PivFigureInput figure_options;
  figure_options.format = plot::parse_figure_format(o.format, "--format");
  if (!o.contour_levels.empty() && !o.contour_step.empty()) {
    throw InputError("--contour-levels and --contour-step exclude each other");
  }
  if (!o.contour_levels.empty()) {
    const auto count = static_cast<std::size_t>(std::count(o.contour_levels.begin(), o.contour_levels.end(), ',')) + 1;
    figure_options.settlement_levels.list = parse_number_list(o.contour_levels, count, "--contour-levels");
  }
  if (!o.contour_step.empty()) {
    figure_options.settlement_levels.step = parse_number_list(o.contour_step, 1, "--contour-step")[0];
    if (!(figure_options.settlement_levels.step > 0.0)) throw InputError("--contour-step must be positive");
  }
  std::vector<fs::path> files(o.images.begin(), o.images.end());
  const fs::path out = o.out;
  const auto start = std::chrono::steady_clock::now();
  std::size_t subsets = 0;
  const PivResult r = run_piv(files, s, [&](std::size_t k, const ImageMeasurements& m) {
    if (k == 0) {
      subsets = m.subset.size();
      if (!o.quiet) fmt::print("{} subsets of {} px every {} px on image 1 ({})\n", subsets, s.subset_size, s.step, o.images[0]);
      return;
    }
    std::size_t valid = 0;
    for (const auto& x : m.subset) valid += x.is_valid();
    if (!o.quiet) {
      fmt::print("image {:>3}/{} {}: {:.2f} s, {:.1f} % valid, reference image {}{}\n", k + 1, o.images.size(),
                 fs::path(o.images[k]).filename().string(), m.seconds,
                 100.0 * static_cast<double>(valid) / std::max<std::size_t>(1, m.subset.size()), m.reference + 1,
                 m.attempts > 1 ? " (reference updated)" : "");
      std::fflush(stdout);
    }
  });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  fs::create_directories(out);
  write_displacements_csv(r, out / "displacements.csv");
  const PixelToModel to_plot = model ? *model : scale_transform(1.0);
  const PivStrainSeries strain = compute_piv_strain(r, to_plot);
  write_piv_h5(out / "piv.h5", r, o.images, model, unit, strain);
  std::vector<fs::path> written{out / "displacements.csv", out / "piv.h5"};
  if (!o.no_figures) {
    PivFigureInput in = figure_options;
    in.result = &r;
    in.strain = &strain;
    in.first_image = read_for_figure(o.images.front());
    in.last_image = read_for_figure(o.images.back());
    in.to_plot = to_plot;
    in.unit = model ? unit : "px";
    in.title = image_label(o.images);
    for (const auto& f : write_piv_figures(out, in)) written.push_back(f);
  }
  if (!o.quiet) {
    double matching = 0.0;
    for (std::size_t k = 1; k < r.image_count(); ++k) matching += r.image[k].seconds;
    fmt::print("{} image pairs in {:.1f} s ({:.0f} subsets per second over the pairs); references used:", r.image_count() - 1,
               seconds, matching > 0 ? static_cast<double>(subsets * (r.image_count() - 1)) / matching : 0.0);
    for (auto ref : r.reference_images) fmt::print(" {}", ref + 1);
    fmt::print("\n  written: ");
    for (std::size_t k = 0; k < written.size(); ++k) fmt::print("{}{}", k ? ", " : "", written[k].filename().string());
    fmt::print(" in {}\n", out.string());
  }
  return 0;
}

int run_synth_command(const SynthOptions& o) {
  if (o.out.empty()) throw InputError("trapdem synth: --out DIR is required");
  if (o.images < 2) throw InputError("--images: at least 2 (image 1 is undeformed)");
  int w = 0, h = 0;
  {
    const auto x = o.size.find('x');
    try {
      if (x == std::string::npos) throw std::invalid_argument(o.size);
      w = std::stoi(o.size.substr(0, x));
      h = std::stoi(o.size.substr(x + 1));
    } catch (const std::exception&) {
      throw InputError(fmt::format("--size '{}': expected WIDTHxHEIGHT in px, e.g. 512x512", o.size));
    }
    if (w < 16 || h < 16) throw InputError(fmt::format("--size '{}': at least 16x16 px", o.size));
  }
  if (o.noise < 0.0) throw InputError("--noise must not be negative");
  SpeckleSettings st;
  st.width = w;
  st.height = h;
  st.noise_std = o.noise;
  st.seed = o.seed;
  const cv::Point2d centre{0.5 * (w - 1), 0.5 * (h - 1)};
  DisplacementField last;
  std::string truth_header, truth_row_format;
  double magnitude = 0.0;
  TrapdoorSettlement t;
  if (o.field == "rigid") {
    magnitude = o.magnitude.value_or(2.5);
    last = rigid_shift(magnitude, 0.6 * magnitude);
  } else if (o.field == "strain") {
    magnitude = o.magnitude.value_or(0.01);
    last = uniform_strain(magnitude, -magnitude, centre);
  } else if (o.field == "shear") {
    magnitude = o.magnitude.value_or(0.01);
    last = simple_shear(magnitude, centre);
  } else if (o.field == "trapdoor") {
    magnitude = o.magnitude.value_or(8.0);
    t.centre_x = centre.x;
    t.width = 0.3 * w;
    t.base_y = 0.85 * h;
    t.settlement = magnitude;
    last = trapdoor_settlement(t);
  } else {
    throw InputError(fmt::format("--field '{}': rigid, strain, shear or trapdoor", o.field));
  }
  std::vector<DisplacementField> fields;
  std::vector<double> factors;
  for (int k = 1; k < o.images; ++k) {
    const double f = static_cast<double>(k) / (o.images - 1);
    factors.push_back(f);
    fields.push_back(scaled(last, f));
  }
  const auto images = synthesize_speckle_sequence(st, fields);
  const fs::path out = o.out;
  fs::create_directories(out);
  std::string truth = "image,file,field,u_px,v_px,exx,eyy,gamma,settlement_px,origin_x_px,origin_y_px,trapdoor_centre_x_px,trapdoor_width_px,trapdoor_base_y_px,band_angle_deg,band_width_px,noise_std\n";
  for (std::size_t k = 0; k < images.size(); ++k) {
    const std::string name = fmt::format("image_{:03d}.png", k + 1);
    const fs::path path = out / name;
    write_atomically(path, [&](const fs::path& tmp) {
      std::vector<uchar> buf;
      if (!cv::imencode(".png", images[k], buf)) throw FileError(path.string() + ": cannot encode PNG");
      std::ofstream f(tmp, std::ios::binary);
      f.write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(buf.size()));
      if (!f) throw FileError(tmp.string() + ": write failed");
    });
    const double f = k == 0 ? 0.0 : factors[k - 1];
    const double m = magnitude * f;
    const bool rigid = o.field == "rigid", strain = o.field == "strain", shear = o.field == "shear",
               trap = o.field == "trapdoor";
    truth += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", k + 1, name, o.field,
                         rigid ? m : 0.0, rigid ? 0.6 * m : 0.0, strain ? m : 0.0, strain ? -m : 0.0,
                         shear ? m : 0.0, trap ? m : 0.0, centre.x, centre.y, trap ? t.centre_x : 0.0,
                         trap ? t.width : 0.0, trap ? t.base_y : 0.0, trap ? t.band_angle_deg : 0.0,
                         trap ? t.band_width : 0.0, o.noise);
  }
  write_text_atomically(out / "truth.csv", truth);
  fmt::print("{} speckle images {}x{} px ({} field, last image magnitude {:g}{}, noise {:g} grey levels) and truth.csv in {}\n",
             images.size(), w, h, o.field, magnitude, (o.field == "strain" || o.field == "shear") ? "" : " px", o.noise,
             out.string());
  return 0;
}

int run_render_command(const RenderOptions& o) {
  const RunFolder run(o.dir);
  const SpecimenGeometry g = load_specimen_geometry(o.config.empty() ? run.resolved_toml() : fs::path(o.config));
  const fs::path h5 = run.snapshots_h5();
  if (!fs::exists(h5)) throw InputError(fmt::format("{}: not found (run `trapdem run` first)", h5.string()));
  const std::vector<Snapshot> snapshots = read_snapshots(h5);
  if (snapshots.empty()) throw InputError(fmt::format("{}: no snapshots", h5.string()));
  CameraSettings cs;
  cs.front_wall_y = g.box_depth;
  const CameraView view = camera_view_for(snapshots, g.box_width, o.px_per_mm, cs);
  const fs::path out = o.out.empty() ? run.camera_dir() : fs::path(o.out);
  fs::create_directories(out);
  std::vector<std::string> files;
  for (std::size_t k = 0; k < snapshots.size(); ++k) {
    const cv::Mat img = render_front_view(snapshots[k], view, cs);
    const fs::path path =
        out / fmt::format("{:03d}_{:g}mm.png", k, std::round(snapshots[k].trapdoor_displacement * 1e4) / 10.0 + 0.0);
    write_atomically(path, [&](const fs::path& tmp) {
      std::vector<uchar> buf;
      if (!cv::imencode(".png", img, buf)) throw FileError(path.string() + ": cannot encode PNG");
      std::ofstream f(tmp, std::ios::binary);
      f.write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(buf.size()));
      if (!f) throw FileError(tmp.string() + ": write failed");
    });
    files.push_back(path.string());
  }
  // PIV from the start of lowering: the images before it (pour, settling, spin-up) are not listed.
  std::vector<double> displacements;
  for (const Snapshot& s : snapshots) displacements.push_back(s.trapdoor_displacement);
  const std::size_t first = lowering_start(displacements);
  std::string listed;
  for (std::size_t k = first; k < files.size(); ++k) listed += files[k] + " ";
  const std::string piv_line = fmt::format("trapdem piv {}--out {}/piv --scale {:g} --origin {:g},{:g}", listed,
                                           out.string(), view.mm_per_px, view.origin_x_mm, view.origin_z_mm);
  write_text_atomically(
      out / "scale.txt",
      fmt::format("# trapdem render: orthographic view through the front window (y = {:g} mm), particles with centres\n"
                  "# within one diameter of it. Pixel (col, row) has its centre at image (x, y) = (col, row), x right,\n"
                  "# y down; model x = origin_x_mm + mm_per_px * x, z (up) = origin_z_mm - mm_per_px * y.\n"
                  "mm_per_px = {:g}\norigin_x_mm = {:g}\norigin_z_mm = {:g}\nwidth_px = {}\nheight_px = {}\n"
                  "lowering_starts_at = {}\n"
                  "# PIV with the model coordinates, from the start of lowering (image {} of {}, {}):\n# {}\n",
                  g.box_depth * 1e3, view.mm_per_px, view.origin_x_mm, view.origin_z_mm, view.width, view.height,
                  fs::path(files[first]).filename().string(), first + 1, files.size(),
                  fs::path(files[first]).filename().string(), piv_line));
  fmt::print("{} images {}x{} px at {:g} px/mm in {} (scale.txt: pixel (0,0) is model ({:g}, {:g}) mm)\n  PIV: {}\n",
             files.size(), view.width, view.height, o.px_per_mm, out.string(), view.origin_x_mm, view.origin_z_mm,
             piv_line);
  if (o.check && snapshots.size() >= 2) {
    PivSettings s;
    const double dmean = 2.0 * snapshots[0].radius[0] * 1e3 * o.px_per_mm;
    s.subset_size = o.subset > 0 ? o.subset : std::max(16, static_cast<int>(std::round(3.0 * dmean / 2.0)) * 2);
    s.step = s.subset_size / 2;
    s.threads = o.threads;
    // Reference: the start of lowering (the analysis' 0 mm), as the suggested PIV.
    std::vector<fs::path> paths(files.begin() + static_cast<std::ptrdiff_t>(first), files.end());
    if (paths.size() < 2) {
      fmt::print("check: no snapshot after the trapdoor started to move\n");
      return 0;
    }
    const PivResult r = run_piv(paths, s);
    fmt::print("check: PIV ({} px subsets, step {} px) from {} against the front-layer particles' mean displacement "
               "per subset\n",
               s.subset_size, s.step, paths.front().filename().string());
    for (std::size_t k = 1; k < r.image_count(); ++k) {
      const CameraAgreement a =
          compare_with_particles(r, k, snapshots[first], snapshots[first + k], view, cs);
      const double delta_mm = snapshots[first + k].trapdoor_displacement * 1e3;
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
