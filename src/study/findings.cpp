#include "study/findings.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace trapdem {

namespace {

std::string join_labels(const std::vector<std::string>& labels) {
  std::string out;
  for (std::size_t k = 0; k < labels.size(); ++k)
    out += (k == 0 ? "" : (k + 1 == labels.size() ? " and " : ", ")) + labels[k];
  return out;
}

}  // namespace

std::string describe_shapes(const std::vector<CaseSummary>& cases) {
  // Shapes in order of first appearance, each with its cases.
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  std::vector<std::string> unknown;
  for (const CaseSummary& c : cases) {
    if (c.shape.empty() || c.shape == "unknown") {
      unknown.push_back(c.label);
      continue;
    }
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == c.shape; });
    if (it == groups.end()) groups.push_back({c.shape, {}}), it = groups.end() - 1;
    it->second.push_back(c.label);
  }
  const std::string missing = unknown.empty() ? "" : fmt::format(" (Not measured in {}.)", join_labels(unknown));
  const std::string rule = "(the shape ratio, the zone's width at mid-height over B: below 1.3 columnar, else elliptical)";
  if (groups.empty()) return "The shape of the zone of influence was not measured in any case.";
  if (groups.size() == 1)
    return fmt::format("The zone of influence is {} in every case{} {}.{}", groups[0].first,
                       unknown.empty() ? "" : " that measured it", rule, missing);
  std::string parts;
  for (std::size_t k = 0; k < groups.size(); ++k)
    parts += fmt::format("{}{} in {}", k == 0 ? "" : (k + 1 == groups.size() ? " and " : ", "), groups[k].first,
                         join_labels(groups[k].second));
  return fmt::format("The zone of influence is {} {}.{}", parts, rule, missing);
}

std::string describe_trend(const std::string& quantity, const std::vector<std::string>& labels,
                           const std::vector<double>& values, double tolerance,
                           const std::function<std::string(double)>& format) {
  std::vector<std::size_t> found;
  std::vector<std::string> missing;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (std::isfinite(values[k]))
      found.push_back(k);
    else
      missing.push_back(labels[k]);
  }
  const std::string missing_note =
      missing.empty() ? "" : fmt::format(" (Not measured in {}.)", join_labels(missing));
  if (found.empty()) return fmt::format("{} was not measured in any case.", quantity);
  if (found.size() == 1)
    return fmt::format("{} is {} in {}, the only case that measured it.{}", quantity, format(values[found[0]]),
                       labels[found[0]], missing_note);

  const std::size_t first = found.front(), last = found.back();
  std::size_t lo = first, hi = first;
  bool every_step_down = true, every_step_up = true;
  for (std::size_t j = 0; j < found.size(); ++j) {
    const double v = values[found[j]];
    if (v < values[lo]) lo = found[j];
    if (v > values[hi]) hi = found[j];
    if (j > 0) {
      const double step = v - values[found[j - 1]];
      every_step_down = every_step_down && step < 0.0;
      every_step_up = every_step_up && step > 0.0;
    }
  }
  const double range = values[hi] - values[lo];
  const double change = values[last] - values[first];
  const std::string from_to = fmt::format("from {} in {} to {} in {}", format(values[first]), labels[first],
                                          format(values[last]), labels[last]);
  const std::string extremes = fmt::format("lowest {} in {}, highest {} in {}", format(values[lo]), labels[lo],
                                           format(values[hi]), labels[hi]);
  std::string sentence;
  if (range <= tolerance) {
    sentence = fmt::format("{} is about the same in every case ({} to {}; differences up to {} are within its "
                           "resolution).", quantity, format(values[lo]), format(values[hi]), format(tolerance));
  } else if (std::abs(change) > tolerance && (every_step_down || every_step_up)) {
    sentence = fmt::format("{} {} {}, at every step of the case order.", quantity, change < 0 ? "falls" : "rises",
                           from_to);
  } else if (std::abs(change) > tolerance) {
    sentence = fmt::format("{} {} {}, but not at every step ({}).", quantity, change < 0 ? "falls" : "rises", from_to,
                           extremes);
  } else {
    sentence = fmt::format("{} ends about where it starts ({}) but varies between ({}).", quantity, from_to, extremes);
  }
  return sentence + missing_note;
}

std::vector<std::string> study_findings(const std::vector<CaseSummary>& cases, double angle_of_draw_deg) {
  std::vector<std::string> labels;
  for (const CaseSummary& c : cases) labels.push_back(c.label);
  auto values = [&](auto get) {
    std::vector<double> v;
    for (const CaseSummary& c : cases) v.push_back(get(c));
    return v;
  };
  auto over_b = [](double x) { return fmt::format("{:.2f} B", x); };
  std::vector<std::string> out;
  // Tolerances: about the resolution of each measurement (docs/study.md): the band angle is fitted
  // to a trace sampled every 2 d; widths and heights come from a grid of d/2 against B ~ 12-25 d.
  out.push_back(describe_trend("The shear band angle to the vertical", labels,
                               values([](const CaseSummary& c) { return c.band_angle_deg; }), 1.0,
                               [](double x) { return fmt::format("{:.1f}°", x); }));
  out.push_back(describe_trend("The height the shear bands reach", labels,
                               values([](const CaseSummary& c) { return c.band_height / c.trapdoor_width; }), 0.1,
                               over_b));
  out.push_back(describe_trend("The shear band width", labels,
                               values([](const CaseSummary& c) { return c.band_width_d; }), 0.5,
                               [](double x) { return fmt::format("{:.1f} d", x); }));
  out.push_back(describe_trend("The zone of influence at the surface", labels,
                               values([](const CaseSummary& c) { return c.zone_surface / c.trapdoor_width; }), 0.1,
                               over_b));
  out.push_back(describe_trend("The zone of influence at mid-height", labels,
                               values([](const CaseSummary& c) { return c.zone_mid_height / c.trapdoor_width; }), 0.1,
                               over_b));
  out.push_back(describe_shapes(cases));
  out.push_back(describe_trend("The least trapdoor load (maximum arching), as a fraction of the load before lowering,",
                               labels, values([](const CaseSummary& c) { return c.min_load_ratio; }), 0.02,
                               [](double x) { return fmt::format("{:.3f}", x); }));

  // The sinkhole: how the practice's estimate stands against the mechanism, case by case.
  std::size_t compared = 0, larger = 0;
  double ratio_lo = INFINITY, ratio_hi = -INFINITY, angle_lo = INFINITY, angle_hi = -INFINITY;
  for (const CaseSummary& c : cases) {
    if (!(std::isfinite(c.dem_surface_diameter) && c.dem_surface_diameter > 0.0 &&
          std::isfinite(c.supposition_surface_diameter)))
      continue;
    ++compared;
    const double ratio = c.supposition_surface_diameter / c.dem_surface_diameter;
    larger += ratio > 1.0;
    ratio_lo = std::min(ratio_lo, ratio);
    ratio_hi = std::max(ratio_hi, ratio);
    angle_lo = std::min(angle_lo, c.angle_from_surface_deg);
    angle_hi = std::max(angle_hi, c.angle_from_surface_deg);
  }
  if (compared > 0) {
    out.push_back(fmt::format(
        "With an angle of draw of {:g}° the scenario supposition gives a larger sinkhole than the DEM's surface zone "
        "of influence in {} of {} cases (supposition over DEM {:.2f} to {:.2f}); the DEM surface zones imply angles "
        "of draw of {:.1f}° to {:.1f}°.",
        angle_of_draw_deg, larger, compared, ratio_lo, ratio_hi, angle_lo, angle_hi));
  } else {
    out.push_back("No case measured a surface zone of influence, so the sinkhole estimates could not be compared.");
  }
  return out;
}

}  // namespace trapdem
