#include "study/findings.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/mechanism_shape.hpp"

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
  const std::string rule = fmt::format("({})", mechanism_shape_rule_text());
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
  std::vector<Spread> single;
  for (double v : values) single.push_back(spread_of({v}));
  return describe_trend(quantity, labels, single, tolerance, format);
}

bool differs_beyond_spread(const Spread& a, const Spread& b, double tolerance) {
  if (a.n == 0 || b.n == 0) return false;
  const double spread = (a.has_sd() ? a.sd : 0.0) + (b.has_sd() ? b.sd : 0.0);
  return std::abs(a.mean - b.mean) > std::max(tolerance, spread);
}

std::string describe_trend(const std::string& quantity, const std::vector<std::string>& labels,
                           const std::vector<Spread>& values, double tolerance,
                           const std::function<std::string(double)>& format) {
  std::vector<std::size_t> found;
  std::vector<std::string> missing;
  bool with_spread = false;
  for (std::size_t k = 0; k < values.size(); ++k) {
    if (values[k].n > 0) {
      found.push_back(k);
      with_spread = with_spread || values[k].has_sd();
    } else {
      missing.push_back(labels[k]);
    }
  }
  const std::string missing_note =
      missing.empty() ? "" : fmt::format(" (Not measured in {}.)", join_labels(missing));
  auto show = [&](std::size_t k) {
    const Spread& v = values[k];
    return v.has_sd() ? fmt::format("{} ± {}", format(v.mean), format(v.sd)) : format(v.mean);
  };
  if (found.empty()) return fmt::format("{} was not measured in any case.", quantity);
  if (found.size() == 1)
    return fmt::format("{} is {} in {}, the only case that measured it.{}", quantity, show(found[0]),
                       labels[found[0]], missing_note);

  const std::size_t first = found.front(), last = found.back();
  std::size_t lo = first, hi = first;
  bool every_step_down = true, every_step_up = true, any_pair_differs = false;
  std::size_t steps_beyond = 0;
  for (std::size_t j = 0; j < found.size(); ++j) {
    const Spread& v = values[found[j]];
    if (v.mean < values[lo].mean) lo = found[j];
    if (v.mean > values[hi].mean) hi = found[j];
    if (j > 0) {
      const double step = v.mean - values[found[j - 1]].mean;
      every_step_down = every_step_down && step < 0.0;
      every_step_up = every_step_up && step > 0.0;
      steps_beyond += differs_beyond_spread(values[found[j - 1]], v, tolerance);
    }
    for (std::size_t i = 0; i < j; ++i)
      any_pair_differs = any_pair_differs || differs_beyond_spread(values[found[i]], v, tolerance);
  }
  const bool ends_differ = differs_beyond_spread(values[first], values[last], tolerance);
  const double change = values[last].mean - values[first].mean;
  const std::string from_to = fmt::format("from {} in {} to {} in {}", show(first), labels[first], show(last),
                                          labels[last]);
  const std::string extremes = fmt::format("lowest {} in {}, highest {} in {}", show(lo), labels[lo], show(hi),
                                           labels[hi]);
  const char* direction = change < 0 ? "falls" : "rises";
  std::string sentence;
  if (!any_pair_differs && !with_spread) {
    sentence = fmt::format("{} is about the same in every case ({} to {}; differences up to {} are within its "
                           "resolution).", quantity, format(values[lo].mean), format(values[hi].mean), format(tolerance));
  } else if (!any_pair_differs) {
    sentence = fmt::format("{} shows no trend beyond the seed-to-seed spread ({} in {} to {} in {}; no two cases' "
                           "means differ by more than the sum of their standard deviations or {}).",
                           quantity, show(lo), labels[lo], show(hi), labels[hi], format(tolerance));
  } else if (ends_differ && (every_step_down || every_step_up)) {
    const std::size_t steps = found.size() - 1;
    const std::string beyond =
        !with_spread ? ""
        : steps_beyond == steps
            ? ", each step beyond the seed-to-seed spread"
            : fmt::format(", beyond the seed-to-seed spread from first to last ({} of {} steps beyond it on their own)",
                          steps_beyond, steps);
    sentence = fmt::format("{} {} {}, at every step of the case order{}.", quantity, direction, from_to, beyond);
  } else if (ends_differ) {
    sentence = fmt::format("{} {} {}, but not at every step ({}){}.", quantity, direction, from_to, extremes,
                           with_spread ? "; first and last differ beyond the seed-to-seed spread" : "");
  } else if (!with_spread) {
    sentence = fmt::format("{} ends about where it starts ({}) but varies between ({}).", quantity, from_to, extremes);
  } else {
    sentence = fmt::format("{} ends within the seed-to-seed spread of where it starts ({}), but some cases differ "
                           "beyond it ({}).", quantity, from_to, extremes);
  }
  return sentence + missing_note;
}

namespace {

std::string angle_text(double x) { return fmt::format("{:.1f}°", x); }

// Without replicates a step beyond the resolution may still be inside the spread between packings
// (at the paper's scale 5-10° in a band angle, ~0.05 in a normalised load: docs/validation.md).
constexpr const char* kSingleRunCaveat =
    "Each case is one run, one packing: the changes below are judged against each quantity's resolution alone, "
    "not against the spread between packings, which one run cannot measure; they describe one realisation of each "
    "case, and a trend among them holds only where replicates (`replicates = N`) show it beyond that spread.";

// One side's band angle with its uncertainty: "4.3 ± 0.6°" (a single run: the fit's standard
// error) or "4.3 ± 1.2° (fit 0.6°)" (replicates: the seeds' standard deviation, and the mean fit error).
std::string band_side(const CaseEnsemble& e, double CaseSummary::*angle, double CaseSummary::*error) {
  const Spread a = e.spread(angle), err = e.spread(error);
  if (a.n == 0) return "—";
  if (a.has_sd()) return fmt::format("{:.1f} ± {:.1f}° (fit {:.1f}°)", a.mean, a.sd, err.mean);
  if (err.n > 0) return fmt::format("{:.1f} ± {:.1f}°", a.mean, err.mean);
  return angle_text(a.mean);
}

}  // namespace

std::vector<std::string> study_findings(const std::vector<CaseSummary>& cases, double angle_of_draw_deg) {
  std::vector<CaseEnsemble> ensembles;
  for (const CaseSummary& c : cases) ensembles.push_back(make_ensemble({c}));
  return study_findings(ensembles, angle_of_draw_deg);
}

std::vector<std::string> study_findings(const std::vector<CaseEnsemble>& ensembles, double angle_of_draw_deg) {
  std::vector<std::string> labels;
  std::vector<CaseSummary> cases;
  bool replicated = false;
  for (const CaseEnsemble& e : ensembles) {
    labels.push_back(e.mean.label);
    cases.push_back(e.mean);
    replicated = replicated || e.replicates.size() > 1;
  }
  auto spreads = [&](auto get) {
    std::vector<Spread> v;
    for (const CaseEnsemble& e : ensembles) v.push_back(e.spread(get));
    return v;
  };
  auto over_b = [](double x) { return fmt::format("{:.2f} B", x); };
  std::vector<std::string> out;
  // The analysis' warnings first: they bound what the other sentences can say.
  for (const CaseEnsemble& e : ensembles)
    for (const CaseSummary& r : e.replicates)
      for (const std::string& w : r.warnings)
        out.push_back(fmt::format("Warning ({}{}): {}.", r.label, r.replicate ? fmt::format(", seed {}", r.seed) : "", w));
  if (replicated)
    out.push_back("Values are means ± the sample standard deviation over each case's packing seeds; a trend is "
                  "claimed only where two cases' means differ by more than the sum of their standard deviations "
                  "(and the quantity's resolution).");
  else if (ensembles.size() > 1)  // one packing a case: say what the sentences below cannot tell
    out.push_back(kSingleRunCaveat);
  // Each band angle with its uncertainty.
  std::string angles;
  for (const CaseEnsemble& e : ensembles) {
    if (!angles.empty()) angles += "; ";
    angles += fmt::format("{} {} / {}", e.mean.label,
                          band_side(e, &CaseSummary::band_angle_left_deg, &CaseSummary::band_angle_left_error_deg),
                          band_side(e, &CaseSummary::band_angle_right_deg, &CaseSummary::band_angle_right_error_deg));
  }
  out.push_back(fmt::format("Band angles to the vertical, left / right, ± the standard error of the trace's fit{}: "
                            "{}.", replicated ? " (with seeds: ± their standard deviation, and the mean fit error)" : "",
                            angles));
  // Tolerances: about the resolution of each measurement (docs/study.md): the band angle is fitted
  // to a trace sampled every 2 d; widths and heights come from a grid of d/2 against B ~ 12-25 d.
  out.push_back(describe_trend("The shear band angle to the vertical", labels,
                               spreads([](const CaseSummary& c) { return c.band_angle_deg; }), 1.0, angle_text));
  out.push_back(describe_trend("The height the shear bands reach", labels,
                               spreads([](const CaseSummary& c) { return c.band_height / c.trapdoor_width; }), 0.1,
                               over_b));
  out.push_back(describe_trend("The shear band width", labels,
                               spreads([](const CaseSummary& c) { return c.band_width_d; }), 0.5,
                               [](double x) { return fmt::format("{:.1f} d", x); }));
  out.push_back(describe_trend("The zone of influence at the surface", labels,
                               spreads([](const CaseSummary& c) { return c.zone_surface / c.trapdoor_width; }), 0.1,
                               over_b));
  out.push_back(describe_trend("The zone of influence at mid-height", labels,
                               spreads([](const CaseSummary& c) { return c.zone_mid_height / c.trapdoor_width; }), 0.1,
                               over_b));
  out.push_back(describe_shapes(cases));
  out.push_back(describe_trend("The least trapdoor load (maximum arching), as a fraction of the load before lowering,",
                               labels, spreads([](const CaseSummary& c) { return c.min_load_ratio; }), 0.02,
                               [](double x) { return fmt::format("{:.3f}", x); }));

  // The element test: the material's strength beside its mechanism (one test per case).
  std::string element;
  for (const CaseSummary& c : cases)
    if (std::isfinite(c.phi_peak_deg) || std::isfinite(c.phi_cs_deg))
      element += fmt::format("{}{} {:.1f}° / {:.1f}°", element.empty() ? "" : ", ", c.label, c.phi_peak_deg, c.phi_cs_deg);
  if (!element.empty()) {
    out.push_back(fmt::format("The virtual element test gives phi'_peak / phi'_cs of {} (the seed's glass beads, "
                              "Table 1: 16.8° / 15.7°).", element));
    // 1°: about the scatter of phi'_cs over the last 5 % of strain in a specimen of a few hundred
    // to a few thousand spheres (docs/element.md).
    std::vector<double> phi_cs;
    for (const CaseSummary& c : cases) phi_cs.push_back(c.phi_cs_deg);
    out.push_back(describe_trend("The critical-state friction angle phi'_cs", labels, phi_cs, 1.0, angle_text));
  }

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
