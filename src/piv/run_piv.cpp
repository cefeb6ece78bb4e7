#include "piv/run_piv.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <sstream>

#include "core/errors.hpp"
#include "piv/image_pair.hpp"
#include "piv/prepared_image.hpp"

namespace trapdem {

namespace {

using Clock = std::chrono::steady_clock;

// The state of the current reference image.
struct Reference {
  std::size_t index = 0;
  std::shared_ptr<const PreparedImage> image;
  std::vector<cv::Point2d> centre;  // px, subset centres in the reference image
  std::vector<cv::Point2d> total;   // px, their total displacement from image 1
  ReferenceSubsets subsets;
};

Reference make_reference(std::size_t index, std::shared_ptr<const PreparedImage> image, const SubsetGrid& grid,
                         const std::vector<cv::Point2d>& total, const std::vector<bool>& alive,
                         const PivSettings& settings) {
  Reference r;
  r.index = index;
  r.image = std::move(image);
  r.total = total;
  r.centre.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) r.centre[i] = grid.centre[i] + total[i];
  r.subsets = make_reference_subsets(*r.image, r.centre, alive, grid.subset_size, settings.texture, settings.threads);
  return r;
}

SubsetStatus status_of(const PairSolution& s, bool textured, const PivSettings& settings) {
  if (!s.attempted) return textured ? SubsetStatus::not_converged : SubsetStatus::low_texture;
  switch (s.best.outcome) {
    case IcgnOutcome::converged:
      if (!textured) return SubsetStatus::low_texture;
      return s.best.zncc >= settings.min_valid_zncc ? SubsetStatus::valid : SubsetStatus::low_correlation;
    case IcgnOutcome::left_image: return SubsetStatus::left_image;
    default: return textured ? SubsetStatus::not_converged : SubsetStatus::low_texture;
  }
}

// The measurements of image k against reference r.
std::vector<SubsetMeasurement> measurements_of(const std::vector<PairSolution>& solution, const Reference& ref,
                                               const PivSettings& settings) {
  std::vector<SubsetMeasurement> out(solution.size());
  for (std::size_t i = 0; i < solution.size(); ++i) {
    SubsetMeasurement& m = out[i];
    if (!ref.subsets.present[i]) continue;  // lost
    m.intensity_std = ref.subsets.intensity_std[i];
    m.sum_squared_gradient = ref.subsets.sum_squared_gradient[i];
    m.status = status_of(solution[i], ref.subsets.textured[i], settings);
    if (!solution[i].attempted) continue;
    const IcgnResult& r = solution[i].best;
    m.zncc = r.zncc;
    m.iterations = r.iterations;
    if (r.outcome == IcgnOutcome::converged) {
      m.relative = r.p;
      m.u = ref.total[i].x + r.p.u;
      m.v = ref.total[i].y + r.p.v;
    }
  }
  return out;
}

// Leapfrog criterion: some textured subset that was matched in the image (not left, lost or
// never reached) fell below the threshold or did not converge.
bool needs_reference_update(const std::vector<SubsetMeasurement>& m, const PivSettings& settings) {
  for (const auto& s : m) {
    if (s.status == SubsetStatus::lost || s.status == SubsetStatus::left_image ||
        s.status == SubsetStatus::low_texture || !std::isfinite(s.zncc))
      continue;
    if (s.status != SubsetStatus::valid || s.zncc < settings.reference_update_zncc) return true;
  }
  return false;
}

// A measurement that may predict the next image and place its subset in a new reference image:
// valid, or converged on a poorly textured subset (which has no better estimate).
bool is_trusted(const SubsetMeasurement& m) {
  return (m.status == SubsetStatus::valid || m.status == SubsetStatus::low_texture) && std::isfinite(m.u) &&
         std::isfinite(m.v);
}

}  // namespace

PivResult run_piv(std::size_t count, const std::function<GreyImage(std::size_t)>& load,
                  const std::function<std::string(std::size_t)>& name, const PivSettings& settings,
                  const PivProgress& progress) {
  if (count < 2) throw InputError("PIV needs at least two images; got " + std::to_string(count));
  auto start_time = Clock::now();
  PivResult result;
  int width = 0, height = 0;
  std::shared_ptr<const PreparedImage> first_image;
  {
    const GreyImage first = load(0);
    width = first.width();
    height = first.height();
    result.grid = make_subset_grid(width, height, settings.roi, settings.subset_size, settings.step);
    first_image = std::make_shared<const PreparedImage>(prepare_image(first));
  }
  const SubsetGrid& grid = result.grid;
  const std::size_t n = grid.size();

  std::vector<bool> alive(n, true);
  Reference ref = make_reference(0, std::move(first_image), grid, std::vector<cv::Point2d>(n), alive, settings);
  result.reference_images.push_back(0);
  {
    ImageMeasurements m0;
    m0.reference = 0;
    m0.subset.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      SubsetMeasurement& s = m0.subset[i];
      s.u = s.v = 0.0;
      s.zncc = 1.0;
      if (!ref.subsets.present[i]) continue;
      s.intensity_std = ref.subsets.intensity_std[i];
      s.sum_squared_gradient = ref.subsets.sum_squared_gradient[i];
      s.status = ref.subsets.textured[i] ? SubsetStatus::valid : SubsetStatus::low_texture;
    }
    m0.seconds = std::chrono::duration<double>(Clock::now() - start_time).count();
    result.image.push_back(std::move(m0));
    if (progress) progress(0, result.image.back());
  }

  std::shared_ptr<const PreparedImage> previous = ref.image;  // image k - 1
  for (std::size_t k = 1; k < count; ++k) {
    start_time = Clock::now();
    const GreyImage grey = load(k);
    if (grey.width() != width || grey.height() != height) {
      std::ostringstream message;
      message << "PIV: image " << name(k) << " is " << grey.width() << " x " << grey.height() << " px but "
              << name(0) << " is " << width << " x " << height << " px; all images must have the same size";
      throw InputError(message.str());
    }
    auto current = std::make_shared<const PreparedImage>(prepare_image(grey));

    ImageMeasurements measured;
    for (int attempt = 1;; ++attempt) {
      // Starts and predictions from the images already done against this reference.
      const ImageMeasurements& last = result.image[k - 1];
      const ImageMeasurements* before_last = k >= 2 ? &result.image[k - 2] : nullptr;
      std::vector<std::optional<WarpParameters>> start(n);
      std::vector<cv::Point2d> prediction(n);
      for (std::size_t i = 0; i < n; ++i) {
        const SubsetMeasurement& a = last.subset[i];
        // Only a trusted measurement predicts the next one.
        if (!is_trusted(a)) continue;
        // The last increment of total displacement, if image k - 2 had the subset too: a steady
        // motion continues (linear extrapolation).
        const bool has_increment = before_last && is_trusted(before_last->subset[i]);
        const cv::Point2d increment =
            has_increment ? cv::Point2d(a.u - before_last->subset[i].u, a.v - before_last->subset[i].v)
                          : cv::Point2d(0.0, 0.0);
        // Image k - 1 measured against this reference: its warp plus the increment. Image k - 1
        // is the reference itself: the increment alone if known, else no start (seeds and the
        // reliability-guided propagation find the subset).
        const bool measured_against_reference = last.reference == ref.index && k - 1 != ref.index;
        prediction[i] = cv::Point2d(a.u - ref.total[i].x, a.v - ref.total[i].y) + increment;
        if (!measured_against_reference && !has_increment) continue;
        WarpParameters p;
        if (measured_against_reference) p = a.relative;
        p.u = prediction[i].x;
        p.v = prediction[i].y;
        start[i] = p;
      }
      const std::vector<PairSolution> solution =
          solve_image_pair(grid, ref.subsets, *ref.image, *current, start, prediction, settings);
      measured.subset = measurements_of(solution, ref, settings);
      measured.reference = ref.index;
      measured.attempts = attempt;
      if (ref.index + 1 >= k || !needs_reference_update(measured.subset, settings)) break;

      // Leapfrog: image k - 1 becomes the reference; subsets it did not track are lost.
      std::vector<cv::Point2d> total(n);
      for (std::size_t i = 0; i < n; ++i) {
        alive[i] = alive[i] && is_trusted(last.subset[i]);
        total[i] = alive[i] ? cv::Point2d(last.subset[i].u, last.subset[i].v) : cv::Point2d(0.0, 0.0);
      }
      ref = make_reference(k - 1, previous, grid, total, alive, settings);
      result.reference_images.push_back(k - 1);
    }
    measured.seconds = std::chrono::duration<double>(Clock::now() - start_time).count();
    result.image.push_back(std::move(measured));
    if (progress) progress(k, result.image.back());
    previous = std::move(current);
  }
  return result;
}

PivResult run_piv(const std::vector<cv::Mat>& images, const PivSettings& settings, const PivProgress& progress) {
  return run_piv(
      images.size(), [&](std::size_t k) { return to_grey_image(images[k]); },
      [](std::size_t k) { return std::to_string(k + 1); }, settings, progress);
}

PivResult run_piv(const std::vector<std::filesystem::path>& files, const PivSettings& settings,
                  const PivProgress& progress) {
  for (const auto& f : files)
    if (!is_readable_image(f)) {
      std::ostringstream message;
      message << "PIV image '" << f.string() << "': "
              << (std::filesystem::exists(f) ? "not an image format OpenCV can read" : "no such file");
      throw InputError(message.str());
    }
  return run_piv(
      files.size(), [&](std::size_t k) { return read_grey_image(files[k]); },
      [&](std::size_t k) {
        std::ostringstream quoted;
        quoted << '\'' << files[k].string() << '\'';
        return quoted.str();
      },
      settings, progress);
}

}  // namespace trapdem
