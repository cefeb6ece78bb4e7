#include "piv/dem_camera.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

namespace {

// The largest view: 134 M px, 1 GiB as one double per pixel (the limit of synth's images, and
// what --check's PIV holds per image at most), estimated from the scale and the particles'
// extent before the size becomes an int or memory (--px-per-mm 1000 over a 0.3 m box: 9e10 px).
constexpr double kMaxViewPixels = 1024.0 * 1024.0 * 1024.0 / sizeof(double);

double largest_diameter(const Snapshot& s) {
  double r = 0.0;
  for (double x : s.radius) r = std::max(r, x);
  return 2.0 * r;
}

double resolved_depth(const Snapshot& s, const CameraSettings& c) {
  return c.layer_depth > 0.0 ? c.layer_depth : largest_diameter(s);
}

// A grey level in [70, 235] from (seed, id): splitmix64.
double particle_grey(std::uint64_t seed, std::int64_t id) {
  std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + static_cast<std::uint64_t>(id) + 0x632BE59BD9B4E019ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return 70.0 + 165.0 * static_cast<double>(z >> 11) / 9007199254740992.0;
}

}  // namespace

std::vector<bool> front_layer(const Snapshot& s, const CameraSettings& c) {
  const double depth = resolved_depth(s, c);
  std::vector<bool> in(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) in[i] = c.front_wall_y - s.position[i].y <= depth;
  return in;
}

CameraView camera_view_for(const std::vector<Snapshot>& snapshots, double box_width_m, double px_per_mm,
                           const CameraSettings& settings) {
  if (!(px_per_mm > 0.0) || !std::isfinite(px_per_mm))
    throw InputError(fmt::format("--px-per-mm {}: expected a finite number > 0", px_per_mm));
  double zlo = 0.0, zhi = -1e300;
  for (const auto& s : snapshots) {
    const auto in = front_layer(s, settings);
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (!in[i]) continue;
      zlo = std::min(zlo, (s.position[i].z - s.radius[i]) * 1e3);
      zhi = std::max(zhi, (s.position[i].z + s.radius[i]) * 1e3);
    }
  }
  if (zhi < -1e299) throw InputError("the snapshots have no particles near the front wall to draw");
  CameraView v;
  v.mm_per_px = 1.0 / px_per_mm;
  zlo -= 2.0, zhi += 2.0;
  v.origin_x_mm = 0.0;
  v.origin_z_mm = std::ceil(zhi * px_per_mm) / px_per_mm;
  const double width_mm = box_width_m * 1e3, height_mm = v.origin_z_mm - zlo;
  const double width = std::ceil(width_mm * px_per_mm) + 1.0, height = std::ceil(height_mm * px_per_mm) + 1.0;
  if (!(width * height <= kMaxViewPixels))  // also NaN and inf (particles or a box out of range)
    throw InputError(fmt::format("--px-per-mm {:g}: the view of {:.4g} x {:.4g} mm would be {:.4g} x {:.4g} px; "
                                 "expected at most {:.3g} px (1 GiB as doubles): a scale of at most {:.3g} px per mm",
                                 px_per_mm, width_mm, height_mm, width, height, kMaxViewPixels,
                                 std::sqrt(kMaxViewPixels / (width_mm * height_mm))));
  v.width = static_cast<int>(width);
  v.height = static_cast<int>(height);
  return v;
}

cv::Mat render_front_view(const Snapshot& s, const CameraView& view, const CameraSettings& c) {
  cv::Mat img(view.height, view.width, CV_32F, cv::Scalar(c.background));
  const auto in = front_layer(s, c);
  std::vector<std::size_t> order;
  for (std::size_t i = 0; i < s.size(); ++i)
    if (in[i]) order.push_back(i);
  // Farthest from the glass first, so nearer particles cover them.
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return s.position[a].y < s.position[b].y; });
  for (std::size_t i : order) {
    const cv::Point2d p = view.to_pixel(s.position[i].x * 1e3, s.position[i].z * 1e3);
    const double r = s.radius[i] * 1e3 / view.mm_per_px;
    const double grey = particle_grey(c.seed, s.id[i]);
    const double hx = p.x - 0.35 * r, hy = p.y - 0.35 * r, hs = 0.2 * r;  // highlight, upper left
    const int c0 = std::max(0, static_cast<int>(std::floor(p.x - r - 1))), c1 = std::min(view.width - 1, static_cast<int>(std::ceil(p.x + r + 1)));
    const int r0 = std::max(0, static_cast<int>(std::floor(p.y - r - 1))), r1 = std::min(view.height - 1, static_cast<int>(std::ceil(p.y + r + 1)));
    for (int row = r0; row <= r1; ++row) {
      float* line = img.ptr<float>(row);
      for (int col = c0; col <= c1; ++col) {
        const double dx = col - p.x, dy = row - p.y;
        const double d = std::sqrt(dx * dx + dy * dy);
        const double cover = std::clamp(r - d + 0.5, 0.0, 1.0);
        if (cover <= 0.0) continue;
        const double rho2 = std::min(1.0, (d * d) / (r * r));
        double value = grey * (0.30 + 0.70 * std::sqrt(1.0 - rho2));
        value += 70.0 * std::exp(-((col - hx) * (col - hx) + (row - hy) * (row - hy)) / (2.0 * hs * hs));
        line[col] = static_cast<float>(line[col] * (1.0 - cover) + std::min(255.0, value) * cover);
      }
    }
  }
  cv::Mat out;
  img.convertTo(out, CV_8U);  // rounds and saturates
  return out;
}

CameraAgreement compare_with_particles(const PivResult& r, std::size_t image, const Snapshot& first,
                                       const Snapshot& current, const CameraView& view,
                                       const CameraSettings& settings) {
  std::unordered_map<std::int64_t, std::size_t> now;
  for (std::size_t i = 0; i < current.size(); ++i) now.emplace(current.id[i], i);
  const auto in = front_layer(first, settings);
  // Particles of the first snapshot binned on the grid's pixel positions.
  struct P {
    cv::Point2d pixel, d;
  };
  std::vector<P> particles;
  for (std::size_t i = 0; i < first.size(); ++i) {
    if (!in[i]) continue;
    const auto it = now.find(first.id[i]);
    if (it == now.end()) continue;
    const Vec3& a = first.position[i];
    const Vec3& b = current.position[it->second];
    const cv::Point2d pa = view.to_pixel(a.x * 1e3, a.z * 1e3), pb = view.to_pixel(b.x * 1e3, b.z * 1e3);
    particles.push_back({pa, pb - pa});
  }
  const double half = 0.5 * r.grid.subset_size;
  CameraAgreement out;
  double se = 0.0, sv = 0.0, bias = 0.0;
  for (std::size_t s = 0; s < r.grid.size(); ++s) {
    const auto& m = r.image[image].subset[s];
    if (!m.is_valid()) continue;
    const cv::Point2d c = r.grid.centre[s];
    cv::Point2d sum{0, 0};
    int n = 0;
    for (const auto& p : particles) {
      if (std::abs(p.pixel.x - c.x) <= half && std::abs(p.pixel.y - c.y) <= half) sum += p.d, ++n;
    }
    if (n == 0) continue;
    const cv::Point2d mean = sum / n;
    const double eu = m.u - mean.x, ev = m.v - mean.y;
    se += eu * eu + ev * ev;
    sv += ev * ev;
    bias += ev;
    out.max_particle_displacement_px = std::max(out.max_particle_displacement_px, std::hypot(mean.x, mean.y));
    ++out.subsets;
  }
  if (out.subsets) {
    const double n = static_cast<double>(out.subsets);
    out.rms_error_px = std::sqrt(se / n);
    out.rms_vertical_error_px = std::sqrt(sv / n);
    out.rms_vertical_error_mm = out.rms_vertical_error_px * view.mm_per_px;
    out.mean_vertical_error_px = bias / n;
  }
  return out;
}

std::size_t lowering_start(const std::vector<double>& displacement) {
  std::size_t first = 0;
  while (first + 1 < displacement.size() && displacement[first + 1] <= 1e-6) ++first;
  return first;
}

}  // namespace trapdem
