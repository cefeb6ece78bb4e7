#include "study/replicate_statistics.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/mechanism_shape.hpp"
#include "analysis/sinkhole.hpp"

namespace trapdem {

namespace {

Json number(double x) { return std::isfinite(x) ? Json(x) : Json(); }

// y(x) on a polyline with x ascending; NaN outside it.
double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty() || at < x.front() || at > x.back()) return kMissing;
  const auto it = std::lower_bound(x.begin(), x.end(), at);
  const std::size_t k = static_cast<std::size_t>(it - x.begin());
  if (x[k] == at || k == 0) return y[k];
  const double t = (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + t * (y[k] - y[k - 1]);
}

double finite_sum(double a, double b) {
  if (!std::isfinite(a)) return b;
  if (!std::isfinite(b)) return a;
  return a + b;
}

}  // namespace

Spread spread_of(const std::vector<double>& values) {
  Spread s;
  double sum = 0.0;
  for (double v : values) {
    if (!std::isfinite(v)) continue;
    ++s.n;
    sum += v;
    s.min = s.n == 1 ? v : std::min(s.min, v);
    s.max = s.n == 1 ? v : std::max(s.max, v);
  }
  if (s.n == 0) return s;
  s.mean = sum / static_cast<double>(s.n);
  if (s.n >= 2) {
    double squares = 0.0;
    for (double v : values)
      if (std::isfinite(v)) squares += (v - s.mean) * (v - s.mean);
    s.sd = std::sqrt(squares / static_cast<double>(s.n - 1));
  }
  return s;
}

Spread scaled(const Spread& s, double factor) {
  Spread out = s;
  out.mean *= factor;
  out.sd *= factor;
  out.min *= factor;
  out.max *= factor;
  return out;
}

Json to_json(const Spread& s) {
  Json j = Json::object();
  j.set("n", static_cast<double>(s.n));
  j.set("mean", number(s.mean));
  j.set("sd", number(s.sd));
  j.set("min", number(s.min));
  j.set("max", number(s.max));
  return j;
}

Spread CaseEnsemble::spread(const std::function<double(const CaseSummary&)>& get) const {
  std::vector<double> values;
  for (const CaseSummary& r : replicates) values.push_back(get(r));
  return spread_of(values);
}

Spread CaseEnsemble::spread(double CaseSummary::*field) const {
  return spread([field](const CaseSummary& r) { return r.*field; });
}

void mean_curve(const std::vector<std::vector<double>>& xs, const std::vector<std::vector<double>>& ys,
                std::vector<double>& x_out, std::vector<double>& y_out) {
  x_out.clear();
  y_out.clear();
  if (xs.empty() || xs.front().empty()) return;
  double reach = xs.front().back();
  for (const auto& x : xs) reach = x.empty() ? -INFINITY : std::min(reach, x.back());
  for (double at : xs.front()) {
    if (at > reach) break;
    double sum = 0.0;
    for (std::size_t k = 0; k < xs.size(); ++k) sum += interpolate(xs[k], ys[k], at);
    x_out.push_back(at);
    y_out.push_back(sum / static_cast<double>(xs.size()));
  }
}

std::string combined_shape(const std::vector<CaseSummary>& replicates) {
  std::size_t columnar = 0, known = 0;
  for (const CaseSummary& r : replicates) {
    if (r.shape.empty() || r.shape == mechanism_shape_name(MechanismShape::unknown)) continue;
    ++known;
    if (r.shape == mechanism_shape_name(MechanismShape::columnar)) ++columnar;
  }
  if (known == 0) return mechanism_shape_name(MechanismShape::unknown);
  if (columnar == 0) return mechanism_shape_name(MechanismShape::elliptical);
  if (columnar == known) return mechanism_shape_name(MechanismShape::columnar);
  return fmt::format("mixed ({} of {} columnar)", columnar, known);
}

CaseSummary combine_replicates(const std::vector<CaseSummary>& replicates) {
  if (replicates.size() == 1) return replicates.front();
  CaseSummary m;
  if (replicates.empty()) return m;
  m.name = replicates.front().name;
  m.label = replicates.front().label;
  CaseEnsemble e;
  e.replicates = replicates;
  for (const SummaryMetric& metric : summary_metrics()) m.*metric.field = e.spread(metric.field).mean;
  m.shape = combined_shape(replicates);
  if (std::isfinite(m.dem_surface_diameter)) m.dem_size_class = size_class_name(classify_sinkhole(m.dem_surface_diameter));
  if (std::isfinite(m.supposition_surface_diameter))
    m.supposition_size_class = size_class_name(classify_sinkhole(m.supposition_surface_diameter));
  std::vector<std::vector<double>> xs, ys;
  for (const CaseSummary& r : replicates) {
    if (r.grc_x_over_b.empty()) continue;
    xs.push_back(r.grc_x_over_b);
    ys.push_back(r.grc_trapdoor_ratio);
  }
  mean_curve(xs, ys, m.grc_x_over_b, m.grc_trapdoor_ratio);
  for (const CaseSummary& r : replicates) {
    m.cost.wall_seconds = finite_sum(m.cost.wall_seconds, r.cost.wall_seconds);
    m.cost.particle_steps = finite_sum(m.cost.particle_steps, r.cost.particle_steps);
    m.cost.segments = finite_sum(m.cost.segments, r.cost.segments);
  }
  m.cost.particles = e.spread([](const CaseSummary& r) { return r.cost.particles; }).mean;
  m.cost.particle_steps_per_second = m.cost.particle_steps / m.cost.wall_seconds;
  return m;
}

CaseEnsemble make_ensemble(std::vector<CaseSummary> replicates) {
  CaseEnsemble e;
  e.mean = combine_replicates(replicates);
  e.replicates = std::move(replicates);
  return e;
}

}  // namespace trapdem
