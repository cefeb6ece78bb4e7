#include "analysis/shear_bands.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/field_smoothing.hpp"
#include "core/errors.hpp"

namespace trapdem {

namespace {

constexpr double nan_value = std::numeric_limits<double>::quiet_NaN();

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

bool in_height_range(double z, double base_z, double height_min, double height_max) {
  const double h = z - base_z;
  return h >= height_min && h <= height_max;
}

double median(std::vector<double> v) {
  if (v.empty()) return nan_value;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// A ridge candidate in one slab: a prominent local maximum of the smoothed profile.
struct Peak {
  std::size_t sample = 0;  // index into the slab's profiles
  double x = 0.0;          // m, refined position
  double value = 0.0;      // smoothed gamma_max
  bool claimed = false;    // already part of a band or branch trace
};

// Both profiles of every slab on one sample grid, which has a sample on the trapdoor centre line.
struct Slab {
  double z_low = 0.0, z = 0.0;
  HorizontalProfile smoothed, raw;
  bool has_data = false;  // any finite smoothed value
};

struct SlabStack {
  std::vector<Slab> slabs;
  std::size_t centre_sample = 0;  // the sample at x = trapdoor centre
};

SlabStack slab_profiles(const TriangleField& raw, const TriangleField& smoothed, const TrapdoorGeometry& trapdoor,
                        const ShearBandSettings& s) {
  const double d = s.mean_diameter;
  const double slab = s.slab_height_diameters * d;
  const double spacing = s.profile_spacing_diameters * d;
  const double kernel = s.kernel_width_diameters * d;
  double x_lo = trapdoor.centre_x, x_hi = trapdoor.centre_x, z_top = trapdoor.base_z;
  for (const auto& c : raw.centroid) {
    x_lo = std::min(x_lo, c.x);
    x_hi = std::max(x_hi, c.x);
    z_top = std::max(z_top, c.z);
  }
  // The grid: centre_x + k * spacing, extended past the data by the half-width search reach so
  // that widths near the side walls and the centre line can be read.
  const double margin = s.max_half_width_diameters * d;
  SlabStack stack;
  stack.centre_sample = static_cast<std::size_t>(std::ceil((trapdoor.centre_x - (x_lo - margin)) / spacing));
  const double x_first = trapdoor.centre_x - static_cast<double>(stack.centre_sample) * spacing;
  const double x_last = x_hi + margin;
  for (double z_low = trapdoor.base_z; z_low <= z_top; z_low += slab) {
    Slab sl;
    sl.z_low = z_low;
    sl.z = z_low + 0.5 * slab;
    sl.smoothed = horizontal_profile(smoothed, z_low, z_low + slab, x_first, x_last, spacing, kernel);
    sl.raw = &smoothed == &raw ? sl.smoothed : horizontal_profile(raw, z_low, z_low + slab, x_first, x_last, spacing, kernel);
    sl.has_data = std::any_of(sl.smoothed.value.begin(), sl.smoothed.value.end(), [](double v) { return std::isfinite(v); });
    stack.slabs.push_back(std::move(sl));
  }
  return stack;
}

// Samples [first, last] of a band's side: up to the centre-line sample included.
struct Segment {
  std::size_t first = 0, last = 0;
};
Segment side_segment(const SlabStack& stack, BandSide side) {
  const std::size_t n = stack.slabs.empty() ? 0 : stack.slabs.front().smoothed.x.size();
  if (n == 0) return {1, 0};
  return side == BandSide::left ? Segment{0, stack.centre_sample} : Segment{stack.centre_sample, n - 1};
}

// Prominent local maxima strictly inside the segment: v[k] > v[k-1], v[k] >= v[k+1], and standing
// above the lower of its two valleys (the lowest value before a higher sample, a NaN or the end
// of the segment, on each side) by at least min_prominence_fraction * v[k]. A maximum on the
// segment's end (the centre line) is not a ridge of this side: the positions found are strictly
// inside, so no trace point can lie on or across the centre line.
std::vector<Peak> prominent_peaks(const HorizontalProfile& p, Segment seg, double min_prominence_fraction) {
  std::vector<Peak> peaks;
  if (seg.last < seg.first + 2) return peaks;
  const auto& v = p.value;
  for (std::size_t k = seg.first + 1; k < seg.last; ++k) {
    if (!std::isfinite(v[k]) || !std::isfinite(v[k - 1]) || !std::isfinite(v[k + 1])) continue;
    if (!(v[k] > v[k - 1] && v[k] >= v[k + 1])) continue;
    double left_valley = v[k], right_valley = v[k];
    for (std::size_t j = k; j-- > seg.first && std::isfinite(v[j]) && v[j] <= v[k];) left_valley = std::min(left_valley, v[j]);
    for (std::size_t j = k + 1; j <= seg.last && std::isfinite(v[j]) && v[j] <= v[k]; ++j) {
      right_valley = std::min(right_valley, v[j]);
    }
    if (v[k] - std::max(left_valley, right_valley) < min_prominence_fraction * v[k]) continue;
    // Parabolic refinement moves at most half a sample: still strictly inside the segment.
    peaks.push_back({k, refined_peak_position(p, k), v[k], false});
  }
  return peaks;
}

struct Chain {
  std::vector<BandTracePoint> trace;
  std::vector<std::pair<std::size_t, std::size_t>> used;  // (slab, peak) per trace point
  std::vector<BandTracePoint> ridge;                       // the smoothed ridge's positions (the trend)
  BandEnd end = BandEnd::top;
  double height_reached = 0.0;
};

// The band's centre and width at one trace point, read off the unsmoothed profile around the
// ridge found on the smoothed one: the mid-point and distance of the half-maximum crossings around
// its largest value within d of the ridge. The smoothed ridge
// decides which band this is; its position is not used as the centre because near the trapdoor
// and the surface the smoothing sees one side only and drags an inclined band's ridge along it
// (by about L tan(angle)). Falls back to the smoothed ridge if a crossing is missing or the
// centre would not lie strictly inside the band's side of the centre line; held within d of the
// smoothed ridge.
struct CentreAndWidth {
  double x = 0.0, width = nan_value;
};
CentreAndWidth centre_and_width(const Slab& slab, Segment seg, double ridge_x, const ShearBandSettings& s) {
  const double d = s.mean_diameter;
  const double reach = d;
  const HorizontalProfile& raw = slab.raw;
  CentreAndWidth out{ridge_x, nan_value};
  const double x_low = std::max(ridge_x - reach, raw.x[seg.first]), x_high = std::min(ridge_x + reach, raw.x[seg.last]);
  const std::size_t peak = index_of_maximum(raw, x_low, x_high);
  if (peak == raw.x.size()) return out;
  const HalfMaximumCrossings half = half_maximum_crossings(raw, peak, s.max_half_width_diameters * d);
  out.width = half.width();
  const double spacing = raw.x[1] - raw.x[0];
  // Kept within d of the ridge: a crossing cut short by a fluctuation must not move the centre
  // off the band.
  const double centre = std::clamp(half.centre(), ridge_x - d, ridge_x + d);
  if (std::isfinite(out.width) && centre > raw.x[seg.first] + 0.5 * spacing && centre < raw.x[seg.last] - 0.5 * spacing) {
    out.x = centre;
  }
  return out;
}

// Follows one ridge upward from its first point (slab `start`, peak `first`), claiming the peaks
// it takes. The rule (docs/analysis.md): the trend is the least-squares line through the last
// direction_points trace points; the next slab's ridge is the unclaimed prominent peak at or
// above the threshold nearest to the trend's prediction, within max_step_diameters of it (while
// fewer than three points give no trend: within slab * tan(max_lean_deg) + d of the last point).
// A slab with no peak in the window is bridged (max_gap_slabs); a nearest peak below the
// threshold ends the band.
Chain follow_ridge(SlabStack& stack, std::vector<std::vector<Peak>>& peaks, Segment seg, std::size_t start,
                   std::size_t first, const TrapdoorGeometry& trapdoor, const ShearBandSettings& s) {
  const double d = s.mean_diameter;
  const double slab_height = s.slab_height_diameters * d;
  Chain chain;
  auto accept = [&](std::size_t k, std::size_t p) {
    Peak& peak = peaks[k][p];
    peak.claimed = true;
    const CentreAndWidth cw = centre_and_width(stack.slabs[k], seg, peak.x, s);
    chain.trace.push_back({stack.slabs[k].z, cw.x, peak.value, cw.width});
    chain.ridge.push_back({stack.slabs[k].z, peak.x, peak.value, 0.0});
    chain.used.emplace_back(k, p);
  };
  accept(start, first);
  std::size_t gap = 0;
  for (std::size_t k = start + 1; k < stack.slabs.size(); ++k) {
    const Slab& slab = stack.slabs[k];
    const BandTracePoint& last = chain.ridge.back();
    if (!slab.has_data) {
      chain.end = BandEnd::top;
      break;
    }
    const double dz = slab.z - last.z;
    double predicted = last.x, tolerance = dz * std::tan(radians(s.max_lean_deg)) + d;
    if (chain.ridge.size() >= 3) {
      const std::size_t n = std::min(chain.ridge.size(), std::max<std::size_t>(3, s.direction_points));
      const std::vector<BandTracePoint> recent(chain.ridge.end() - static_cast<long>(n), chain.ridge.end());
      const TraceLineFit trend = fit_trace_line(recent, 0.0, -std::numeric_limits<double>::infinity(),
                                                std::numeric_limits<double>::infinity());
      if (std::isfinite(trend.slope)) {
        predicted = last.x + trend.slope * dz;
        tolerance = s.max_step_diameters * d * dz / slab_height;
      }
    }
    // Each candidate scores its value times a Gaussian of its offset from the prediction (standard
    // deviation half the window): a strong ridge slightly off the trend beats a weak bump on it.
    std::size_t best = peaks[k].size(), best_below = peaks[k].size();
    const auto score = [&](const Peak& peak) {
      const double u = (peak.x - predicted) / (0.5 * tolerance);
      return peak.value * std::exp(-0.5 * u * u);
    };
    for (std::size_t p = 0; p < peaks[k].size(); ++p) {
      const Peak& peak = peaks[k][p];
      if (peak.claimed || std::abs(peak.x - predicted) > tolerance) continue;
      auto& slot = peak.value >= s.ridge_threshold ? best : best_below;
      if (slot == peaks[k].size() || score(peak) > score(peaks[k][slot])) slot = p;
    }
    if (best < peaks[k].size()) {
      accept(k, best);
      gap = 0;
      continue;
    }
    if (best_below < peaks[k].size()) {
      // The ridge crosses the threshold between the last traced slab and this one (linear).
      const double value = peaks[k][best_below].value;
      chain.end = BandEnd::below_threshold;
      chain.height_reached = last.z + (last.peak - s.ridge_threshold) / (last.peak - value) * dz - trapdoor.base_z;
      return chain;
    }
    // No ridge in the window. Where the window reaches the centre line and the profile's highest
    // value in the window (on this side) is on the centre line and above the threshold, the ridge
    // has run into the centre line: it meets the other band there.
    const std::size_t c = seg.first == 0 ? seg.last : seg.first;
    const HorizontalProfile& sp = slab.smoothed;
    if (std::abs(sp.x[c] - predicted) <= tolerance) {
      const std::size_t top = index_of_maximum(sp, std::max(predicted - tolerance, sp.x[seg.first]),
                                               std::min(predicted + tolerance, sp.x[seg.last]));
      if (top == c && sp.value[c] >= s.ridge_threshold) {
        chain.end = BandEnd::centre_line;
        break;
      }
    }
    if (++gap > s.max_gap_slabs) {
      chain.end = BandEnd::lost;
      break;
    }
  }
  chain.height_reached = chain.trace.back().z - trapdoor.base_z;
  return chain;
}

// Main-band x at height z: linear between trace points, held at the ends.
double trace_x_at(const std::vector<BandTracePoint>& trace, double z) {
  if (z <= trace.front().z) return trace.front().x;
  for (std::size_t k = 1; k < trace.size(); ++k) {
    if (z <= trace[k].z) {
      const double f = (z - trace[k - 1].z) / (trace[k].z - trace[k - 1].z);
      return trace[k - 1].x + f * (trace[k].x - trace[k - 1].x);
    }
  }
  return trace.back().x;
}

// Where a branch leaves the band: going down from the branch's first point, the height where the
// line fitted through the branch's first points meets the band's trace; the branch's first
// point if the two do not meet below it.
double branch_height(const std::vector<BandTracePoint>& band, const std::vector<BandTracePoint>& branch,
                     std::size_t direction_points, double slab_height, double base_z) {
  const std::size_t n = std::min(branch.size(), std::max<std::size_t>(3, direction_points));
  const std::vector<BandTracePoint> first(branch.begin(), branch.begin() + static_cast<long>(n));
  const TraceLineFit line = fit_trace_line(first, 0.0, -std::numeric_limits<double>::infinity(),
                                           std::numeric_limits<double>::infinity());
  const double z_start = branch.front().z;
  if (!std::isfinite(line.slope)) return z_start - base_z;
  const auto gap = [&](double z) { return line.intercept + line.slope * z - trace_x_at(band, z); };
  const double g0 = gap(z_start);
  const double step = 0.25 * slab_height;
  for (double z = z_start - step; z >= band.front().z - 1e-12; z -= step) {
    const double g = gap(z);
    if ((g > 0.0) != (g0 > 0.0) || g == 0.0) {  // crossed between z and z + step (linear)
      const double g_above = gap(z + step);
      return z + step * g_above / (g_above - g) - base_z;
    }
  }
  return z_start - base_z;
}

void fill_band_metrics(ShearBand& band, const TrapdoorGeometry& trapdoor, const ShearBandSettings& s) {
  const double d = s.mean_diameter;
  const TraceLineFit fit = fit_trace_line(band.trace, trapdoor.base_z, s.fit_height_min, s.fit_height_max);
  band.angle_deg = band_angle_from_slope(fit.slope, band.side);
  band.angle_error_deg = band_angle_error_from_fit(fit);
  const TraceLineFit base = fit_trace_line(band.trace, trapdoor.base_z, 0.0, s.base_fit_height_diameters * d);
  band.base_angle_deg = band_angle_from_slope(base.slope, band.side);
  band.base_angle_error_deg = band_angle_error_from_fit(base);
  band.width_diameters =
      band_normal_width(band.trace, band.angle_deg, trapdoor.base_z, s.fit_height_min, s.fit_height_max) / d;
}

void check_settings(const TrapdoorGeometry& trapdoor, const ShearBandSettings& s) {
  if (!(s.mean_diameter > 0.0)) throw InputError("trace_shear_band: mean_diameter must be positive (m)");
  if (!(trapdoor.width > 0.0)) throw InputError("trace_shear_band: trapdoor width must be positive (m)");
  if (!(s.smoothing_diameters >= 0.0) || !std::isfinite(s.smoothing_diameters)) {
    throw InputError("trace_shear_band: smoothing_diameters must be a finite number >= 0 (d)");
  }
}

// Mean squared horizontal distance (m^2) of `points` from the line fitted through `line_points`;
// NaN if that line cannot be fitted (fewer than three points).
double misfit_to_line(const std::vector<BandTracePoint>& points, const std::vector<BandTracePoint>& line_points) {
  const TraceLineFit fit = fit_trace_line(line_points, 0.0, -std::numeric_limits<double>::infinity(),
                                          std::numeric_limits<double>::infinity());
  if (!std::isfinite(fit.slope) || points.empty()) return nan_value;
  double sum = 0.0;
  for (const auto& p : points) {
    const double r = p.x - (fit.intercept + fit.slope * p.z);
    sum += r * r;
  }
  return sum / static_cast<double>(points.size());
}

// The band is the continuation in line with it at a branch point. A band does not turn where a
// branch leaves it (the seed paper's branches leave the main bands at an angle near the top), but
// the tracer decides slab by slab: where a fluctuation interrupts the band for a slab or two just
// where a branch parts, the branch's ridge is the only one in the step window and the trace turns
// onto it; the band's own continuation is then found above as a "branch" of it. Decided here at
// each branch height (where the branch's line meets the trace): the line through the first
// direction_points points of each continuation (the trace above, the branch) is extended down,
// and the one passing nearer (mean squared distance) to the trace's last 2 direction_points
// points below is the band. Position and direction both count: the two ridges merge over ~6 d
// near the parting point (docs/analysis.md), which bends the last few points below toward the
// branch, so a direction read there alone would favour the branch. If the branch wins, the two
// swap: the band runs on along the branch's ridge (with its end), and what the trace followed
// from where it left the band becomes the branch.
void keep_the_continuation_in_line(Chain& main, Chain& branch, const TrapdoorGeometry& trapdoor,
                                   const ShearBandSettings& s) {
  const double slab_height = s.slab_height_diameters * s.mean_diameter;
  const double split_z =
      trapdoor.base_z + branch_height(main.trace, branch.trace, s.direction_points, slab_height, trapdoor.base_z);
  const auto above = std::find_if(main.trace.begin(), main.trace.end(),
                                  [&](const BandTracePoint& p) { return p.z > split_z; });
  const std::size_t n = std::max<std::size_t>(3, s.direction_points);
  const auto below_count = static_cast<std::size_t>(above - main.trace.begin());
  const auto above_count = static_cast<std::size_t>(main.trace.end() - above);
  if (below_count < 3 || above_count < 3 || branch.trace.size() < 3) return;
  const std::vector<BandTracePoint> below(above - static_cast<long>(std::min(2 * n, below_count)), above);
  const std::vector<BandTracePoint> main_above(above, above + static_cast<long>(std::min(n, above_count)));
  const std::vector<BandTracePoint> branch_start(branch.trace.begin(),
                                                 branch.trace.begin() + static_cast<long>(std::min(n, branch.trace.size())));
  if (!(misfit_to_line(below, branch_start) < misfit_to_line(below, main_above))) return;
  // Where the trace left the band: the last points below the split that lie nearer the line of
  // the trace above (now the branch) than the band's line went with the branch (at most
  // direction_points of them), so that the branch's height is read where it parts.
  auto parting = above;
  for (std::size_t moved = 0; moved < n && parting - main.trace.begin() > 3; ++moved) {
    const std::vector<BandTracePoint> point(parting - 1, parting);
    if (!(misfit_to_line(point, main_above) < misfit_to_line(point, branch_start))) break;
    --parting;
  }
  Chain band_on = main, branch_on = branch;
  band_on.trace.assign(main.trace.begin(), parting);
  band_on.trace.insert(band_on.trace.end(), branch.trace.begin(), branch.trace.end());
  band_on.end = branch.end;
  band_on.height_reached = branch.height_reached;
  branch_on.trace.assign(parting, main.trace.end());
  branch_on.end = main.end;
  branch_on.height_reached = main.height_reached;
  main = std::move(band_on);
  branch = std::move(branch_on);
}

ShearBand trace_on(SlabStack& stack, const TrapdoorGeometry& trapdoor, const ShearBandSettings& s, BandSide side) {
  const double d = s.mean_diameter;
  ShearBand band;
  band.side = side;
  const Segment seg = side_segment(stack, side);
  std::vector<std::vector<Peak>> peaks(stack.slabs.size());
  for (std::size_t k = 0; k < stack.slabs.size(); ++k) {
    peaks[k] = prominent_peaks(stack.slabs[k].smoothed, seg, s.min_prominence_fraction);
  }
  if (stack.slabs.empty() || !stack.slabs.front().has_data) {
    fill_band_metrics(band, trapdoor, s);
    return band;
  }
  // The first slab: the highest ridge within base_search_fraction * B of the edge.
  const double edge = side == BandSide::left ? trapdoor.left_edge() : trapdoor.right_edge();
  const double reach = s.base_search_fraction * trapdoor.width;
  std::size_t first = peaks[0].size();
  for (std::size_t p = 0; p < peaks[0].size(); ++p) {
    if (std::abs(peaks[0][p].x - edge) > reach) continue;
    if (first == peaks[0].size() || peaks[0][p].value > peaks[0][first].value) first = p;
  }
  if (first == peaks[0].size() || peaks[0][first].value < s.ridge_threshold) {
    fill_band_metrics(band, trapdoor, s);  // no band: end none, height 0
    return band;
  }
  Chain main = follow_ridge(stack, peaks, seg, 0, first, trapdoor, s);

  // Branches: a ridge at or above the threshold that appears within branch_reach of the band
  // (no unclaimed ridge at or above the threshold within the step window below it: it grows out
  // of the band), followed upward by the same rule; kept if followed over min_branch_height with
  // a median ridge value of at least min_branch_peak_fraction of the band's (a band, not a
  // fluctuation of the background).
  const double slab_height = s.slab_height_diameters * d;
  const double window = slab_height * std::tan(radians(s.max_lean_deg)) + d;
  const std::size_t last_slab = main.used.back().first;
  std::vector<double> main_peaks;
  for (const auto& q : main.trace) main_peaks.push_back(q.peak);
  const double band_peak = median(std::move(main_peaks));
  std::vector<Chain> branches;
  for (std::size_t k = 1; k <= std::min(last_slab + 1, stack.slabs.size() - 1); ++k) {
    const double x_band = trace_x_at(main.trace, stack.slabs[k].z);
    for (std::size_t p = 0; p < peaks[k].size(); ++p) {
      const Peak& peak = peaks[k][p];
      if (peak.claimed || peak.value < s.ridge_threshold) continue;
      if (std::abs(peak.x - x_band) > s.branch_reach_diameters * d) continue;
      const bool continues_lower_ridge = std::any_of(peaks[k - 1].begin(), peaks[k - 1].end(), [&](const Peak& q) {
        return !q.claimed && q.value >= s.ridge_threshold && std::abs(q.x - peak.x) <= window;
      });
      if (continues_lower_ridge) continue;
      Chain chain = follow_ridge(stack, peaks, seg, k, p, trapdoor, s);
      const double height = chain.trace.back().z - chain.trace.front().z + slab_height;
      std::vector<double> branch_peaks;
      for (const auto& q : chain.trace) branch_peaks.push_back(q.peak);
      if (height < s.min_branch_height_diameters * d ||
          median(std::move(branch_peaks)) < s.min_branch_peak_fraction * band_peak) {
        for (const auto& [slab, q] : chain.used) peaks[slab][q].claimed = false;
        continue;
      }
      branches.push_back(std::move(chain));
    }
  }
  std::sort(branches.begin(), branches.end(),
            [](const Chain& a, const Chain& b) { return a.trace.front().z < b.trace.front().z; });
  for (Chain& branch : branches) keep_the_continuation_in_line(main, branch, trapdoor, s);

  band.trace = main.trace;
  band.end = main.end;
  band.height_reached = main.height_reached;
  fill_band_metrics(band, trapdoor, s);
  for (const Chain& chain : branches) {
    BandBranch branch;
    branch.trace = chain.trace;
    branch.height = branch_height(band.trace, chain.trace, s.direction_points, slab_height, trapdoor.base_z);
    const TraceLineFit fit = fit_trace_line(chain.trace, trapdoor.base_z, -std::numeric_limits<double>::infinity(),
                                            std::numeric_limits<double>::infinity());
    branch.angle_deg = band_angle_from_slope(fit.slope, side);
    branch.angle_error_deg = band_angle_error_from_fit(fit);
    band.branches.push_back(std::move(branch));
  }
  std::sort(band.branches.begin(), band.branches.end(),
            [](const BandBranch& a, const BandBranch& b) { return a.height < b.height; });
  return band;
}

}  // namespace

const char* band_end_name(BandEnd end) {
  switch (end) {
    case BandEnd::none: return "none";
    case BandEnd::below_threshold: return "below_threshold";
    case BandEnd::centre_line: return "centre_line";
    case BandEnd::lost: return "lost";
    case BandEnd::top: return "top";
  }
  return "unknown";
}

TraceLineFit fit_trace_line(const std::vector<BandTracePoint>& trace, double base_z, double height_min,
                            double height_max) {
  TraceLineFit fit;
  std::vector<const BandTracePoint*> used;
  for (const auto& p : trace) {
    if (in_height_range(p.z, base_z, height_min, height_max)) used.push_back(&p);
  }
  fit.points = used.size();
  if (used.size() < 3) return fit;
  const double n = static_cast<double>(used.size());
  double z_mean = 0.0, x_mean = 0.0;
  for (const auto* p : used) {
    z_mean += p->z / n;
    x_mean += p->x / n;
  }
  double szz = 0.0, szx = 0.0;
  for (const auto* p : used) {
    szz += (p->z - z_mean) * (p->z - z_mean);
    szx += (p->z - z_mean) * (p->x - x_mean);
  }
  if (!(szz > 0.0)) return fit;
  fit.slope = szx / szz;
  fit.intercept = x_mean - fit.slope * z_mean;
  std::vector<double> r;
  for (const auto* p : used) r.push_back(p->x - (fit.intercept + fit.slope * p->z));
  double srr = 0.0, lag = 0.0;
  for (std::size_t k = 0; k < r.size(); ++k) {
    srr += r[k] * r[k];
    if (k + 1 < r.size()) lag += r[k] * r[k + 1];
  }
  fit.residual_correlation = srr > 0.0 ? lag / srr : 0.0;
  const double rho = std::max(0.0, fit.residual_correlation);
  const double n_eff = n * (1.0 - rho) / (1.0 + rho);
  if (n_eff > 2.0) fit.slope_error = std::sqrt(srr / (n_eff - 2.0) / szz);
  return fit;
}

double band_angle_from_slope(double slope, BandSide side) {
  if (!std::isfinite(slope)) return nan_value;
  return degrees(std::atan(side == BandSide::left ? -slope : slope));
}

double band_angle_error_from_fit(const TraceLineFit& fit) {
  if (!std::isfinite(fit.slope) || !std::isfinite(fit.slope_error)) return nan_value;
  return degrees(fit.slope_error / (1.0 + fit.slope * fit.slope));
}

double band_angle_deg(const std::vector<BandTracePoint>& trace, BandSide side, double base_z, double height_min,
                      double height_max) {
  return band_angle_from_slope(fit_trace_line(trace, base_z, height_min, height_max).slope, side);
}

double band_normal_width(const std::vector<BandTracePoint>& trace, double angle_deg, double base_z,
                         double height_min, double height_max) {
  // A band at angle a to the vertical cut by a horizontal line: normal width = horizontal * cos(a).
  const double cosine = std::isfinite(angle_deg) ? std::cos(radians(angle_deg)) : 1.0;
  std::vector<double> widths;
  for (const auto& p : trace) {
    if (in_height_range(p.z, base_z, height_min, height_max) && std::isfinite(p.horizontal_width)) {
      widths.push_back(p.horizontal_width * cosine);
    }
  }
  return median(std::move(widths));
}

ShearBand trace_shear_band(const TriangleField& gamma_max, const TriangleField& smoothed,
                           const TrapdoorGeometry& trapdoor, const ShearBandSettings& s, BandSide side) {
  check_settings(trapdoor, s);
  SlabStack stack = slab_profiles(gamma_max, smoothed, trapdoor, s);
  return trace_on(stack, trapdoor, s, side);
}

ShearBandPair trace_shear_bands(const TriangleField& gamma_max, const TriangleField& smoothed,
                                const TrapdoorGeometry& trapdoor, const ShearBandSettings& s) {
  check_settings(trapdoor, s);
  if (smoothed.size() != gamma_max.size()) {
    throw InputError("trace_shear_bands: the smoothed field has " + std::to_string(smoothed.size()) +
                     " triangles, the strain field " + std::to_string(gamma_max.size()));
  }
  SlabStack stack = slab_profiles(gamma_max, smoothed, trapdoor, s);
  return {trace_on(stack, trapdoor, s, BandSide::left), trace_on(stack, trapdoor, s, BandSide::right)};
}

ShearBandPair trace_shear_bands(const TriangleField& gamma_max, const TrapdoorGeometry& trapdoor,
                                const ShearBandSettings& s) {
  check_settings(trapdoor, s);
  const TriangleField smoothed = smooth_triangle_field(gamma_max, s.smoothing_diameters * s.mean_diameter);
  return trace_shear_bands(gamma_max, smoothed, trapdoor, s);
}

}  // namespace trapdem
