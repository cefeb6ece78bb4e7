#include "piv/piv_folder.hpp"

#include <chrono>

#include <fmt/format.h>
#include <opencv2/imgcodecs.hpp>

#include "core/errors.hpp"
#include "piv/control_point_file.hpp"
#include "piv/displacement_csv.hpp"
#include "piv/piv_strain.hpp"

namespace trapdem {

namespace fs = std::filesystem;

namespace {

std::string image_label(const std::vector<fs::path>& images) {
  if (images.empty()) return "PIV";
  return fmt::format("PIV {} … {}", images.front().filename().string(), images.back().filename().string());
}

cv::Mat read_for_figure(const fs::path& file) {
  const cv::Mat m = cv::imread(file.string(), cv::IMREAD_ANYDEPTH | cv::IMREAD_ANYCOLOR);
  if (m.empty()) throw InputError(fmt::format("{}: cannot be read as an image", file.string()));
  return to_grey8(m);
}

}  // namespace

PivFolderResult run_piv_into_folder(const PivFolderOptions& o, const PivProgress& progress) {
  if (o.images.size() < 2) throw InputError("PIV: give at least two images, in order");
  if (o.out.empty()) throw InputError("PIV: an output folder is required");
  if (o.scale_mm_per_px && !o.control_points.empty())
    throw InputError("a scale and control points exclude each other");
  PivFolderResult out;
  std::optional<PixelToModel> model;
  out.unit = "px";
  if (o.scale_mm_per_px) {
    if (!(*o.scale_mm_per_px > 0.0)) throw InputError("the scale must be positive (mm per px)");
    model = scale_transform(*o.scale_mm_per_px,
                            {-o.origin_mm[0] / *o.scale_mm_per_px, o.origin_mm[1] / *o.scale_mm_per_px});
    out.unit = "mm";
  } else if (!o.control_points.empty()) {
    out.control_points = read_control_points(o.control_points);
    out.fit = fit_control_points(out.control_points, o.fit);
    model = out.fit->transform;
    out.unit = "model units";
  }

  const auto start = std::chrono::steady_clock::now();
  out.result = run_piv(o.images, o.settings, [&](std::size_t k, const ImageMeasurements& m) {
    if (k == 0) out.subsets = m.subset.size();
    if (progress) progress(k, m);
  });
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::error_code ec;
  fs::create_directories(o.out, ec);
  if (ec) throw FileError(fmt::format("cannot create the output folder {}: {}", o.out.string(), ec.message()));
  write_displacements_csv(out.result, o.out / "displacements.csv");
  const PixelToModel to_plot = model ? *model : scale_transform(1.0);
  out.strain = compute_piv_strain(out.result, to_plot);
  std::vector<std::string> names;
  for (const fs::path& image : o.images) names.push_back(image.string());
  write_piv_h5(o.out / "piv.h5", out.result, names, model, out.unit, out.strain);
  out.written = {o.out / "displacements.csv", o.out / "piv.h5"};
  if (o.figures) {
    PivFigureInput in;
    in.format = o.format;
    in.settlement_levels = o.settlement_levels;
    in.result = &out.result;
    in.strain = &out.strain;
    in.first_image = read_for_figure(o.images.front());
    in.last_image = read_for_figure(o.images.back());
    in.to_plot = to_plot;
    in.unit = model ? out.unit : "px";
    in.title = image_label(o.images);
    for (const fs::path& f : write_piv_figures(o.out, in)) out.written.push_back(f);
  }
  return out;
}

}  // namespace trapdem
