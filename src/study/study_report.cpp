#include "study/study_report.hpp"

#include <cmath>

#include <fmt/format.h>

#include "core/length_text.hpp"
#include "io/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/text_escape.hpp"
#include "plot/colour_map.hpp"
#include "plot/line_chart.hpp"
#include "plot/specimen_figures.hpp"
#include "study/findings.hpp"
#include "study/parameter_differences.hpp"

namespace fs = std::filesystem;

namespace trapdem {

namespace {

// A number for the page: "—" where it was not measured.
std::string cell(double x, const char* format) {
  return std::isfinite(x) ? fmt::format(fmt::runtime(format), x) : "—";
}

std::string csv_number(double x) { return std::isfinite(x) ? fmt::format("{:.6g}", x) : ""; }

std::string duration(double s) {
  if (!std::isfinite(s)) return "—";
  if (s < 120.0) return fmt::format("{:.0f} s", s);
  if (s < 7200.0) return fmt::format("{:.1f} min", s / 60.0);
  return fmt::format("{:.1f} h", s / 3600.0);
}

std::string contour_file(const StudyCaseResult& c) { return "contours_" + c.summary.name + ".png"; }

void write_ground_reaction_chart(const fs::path& png, const StudyReportInput& in) {
  plot::LineChart chart;
  chart.title = "Ground reaction curves";
  chart.subtitle = "trapdoor stress over its value before lowering";
  chart.x_label = "trapdoor displacement / trapdoor width  δ/B (-)";
  chart.y_label = "trapdoor stress / stress before lowering (-)";
  chart.reference_y = {1.0};
  for (std::size_t k = 0; k < in.cases.size(); ++k) {
    const CaseSummary& s = in.cases[k].summary;
    plot::LineSeries series;
    series.name = s.label;
    series.colour = plot::series_colour(k);
    series.x = s.grc_x_over_b;
    series.y = s.grc_trapdoor_ratio;
    chart.series.push_back(std::move(series));
  }
  plot::write_line_chart_png(png, chart);
}

std::string metrics_csv(const StudyReportInput& in) {
  std::string out =
      "case,label,trapdoor_width_m,travel_m,band_angle_deg,band_angle_left_deg,band_angle_right_deg,band_height_m,"
      "band_width_diameters,zone_surface_m,zone_mid_height_m,shape_ratio,min_load_ratio,min_load_at_over_B,"
      "final_load_ratio,dem_surface_diameter_prototype_m,supposition_surface_diameter_prototype_m,wall_seconds,"
      "particle_steps_per_second,particles\n";
  for (const StudyCaseResult& c : in.cases) {
    const CaseSummary& s = c.summary;
    const double row[] = {s.trapdoor_width, s.travel, s.band_angle_deg, s.band_angle_left_deg, s.band_angle_right_deg,
                          s.band_height, s.band_width_d, s.zone_surface, s.zone_mid_height, s.shape_ratio,
                          s.min_load_ratio, s.min_load_at_over_b, s.final_load_ratio, s.dem_surface_diameter,
                          s.supposition_surface_diameter, s.cost.wall_seconds, s.cost.particle_steps_per_second,
                          s.cost.particles};
    // Appended piece by piece: `out += a + "," + b` trips GCC 12's false -Wrestrict (GCC bug 105651).
    out += s.name;
    out += ',';
    out += s.label;
    for (double x : row) {
      out += ',';
      out += csv_number(x);
    }
    out += "\n";
  }
  return out;
}

const char* kStyle = R"(
body { font-family: "DejaVu Sans", Arial, sans-serif; color: #222; margin: 0; background: #fafafa; line-height: 1.45; }
main { max-width: 1180px; margin: 0 auto; padding: 1.2em 1.5em 3em; background: #fff; }
h1 { font-size: 1.6em; margin-bottom: 0.2em; } h2 { font-size: 1.25em; margin-top: 1.8em; border-bottom: 1px solid #ddd; }
p.lead { color: #555; margin-top: 0; }
figure { margin: 1em 0; } figure img { max-width: 100%; height: auto; border: 1px solid #eee; }
figure.chart img { max-width: 820px; width: 100%; }
figcaption { color: #555; font-size: 0.9em; }
.grid { display: grid; grid-template-columns: repeat(auto-fit, minmax(420px, 1fr)); gap: 0.8em; }
table { border-collapse: collapse; font-size: 0.9em; margin: 0.6em 0; }
th, td { border: 1px solid #ddd; padding: 0.3em 0.6em; text-align: right; }
th { background: #f0f0f0; } td.l, th.l { text-align: left; }
.scroll { overflow-x: auto; }
ul.findings li { margin-bottom: 0.4em; }
.note { color: #8a5a00; }
)";

}  // namespace

fs::path write_study_report(const fs::path& dir, const StudyReportInput& in) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FileError(fmt::format("cannot create the report folder {}: {}", dir.string(), ec.message()));

  // Figures first: the page never points at an image that is not there.
  std::vector<const AnalysisResult*> finals;
  for (const StudyCaseResult& c : in.cases)
    if (c.final_analysis) finals.push_back(c.final_analysis);
  double vmax = in.settings.max_strain;
  if (!(vmax > 0.0))
    for (const AnalysisResult* r : finals) vmax = std::max(vmax, plot::auto_strain_scale(*r));
  const bool has_panel = !finals.empty();
  if (has_panel) plot::write_strain_panel_png(dir / "strain_panel.png", finals, vmax);
  for (const StudyCaseResult& c : in.cases)
    if (c.contour_analysis) plot::write_displacement_contours_png(dir / contour_file(c), *c.contour_analysis, 900);
  write_ground_reaction_chart(dir / "ground_reaction.png", in);

  std::vector<CaseSummary> summaries;
  std::vector<std::vector<std::pair<std::string, std::string>>> parameters;
  for (const StudyCaseResult& c : in.cases) {
    summaries.push_back(c.summary);
    parameters.push_back(c.parameters);
  }
  const std::vector<std::string> findings = study_findings(summaries, in.settings.angle_of_draw_deg);
  const std::vector<ParameterDifference> differences = differing_parameters(parameters);

  Json summary = Json::object();
  summary.set("study", in.study_name);
  summary.set("scale", in.scale);
  Json cases = Json::array();
  for (const CaseSummary& s : summaries) cases.push_back(to_json(s));
  summary.set("cases", cases);
  Json finding_list = Json::array();
  for (const std::string& f : findings) finding_list.push_back(f);
  summary.set("findings", finding_list);
  summary.set("strain_scale_max", vmax);
  write_text_atomically(dir / "summary.json", summary.dump() + "\n");
  write_text_atomically(dir / "metrics.csv", metrics_csv(in));

  const std::string contours_at = format_mm(in.settings.contours_at);
  std::string h;
  h += "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  h += "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n";
  h += fmt::format("<title>{} — trapdem study report</title>\n", markup_escape(in.study_name));
  h += "<link rel=\"icon\" href=\"data:,\">\n";  // no favicon request: the page stays offline and error-free
  h += fmt::format("<style>{}</style>\n</head>\n<body>\n<main>\n", kStyle);
  h += fmt::format("<h1>Study {}</h1>\n<p class=\"lead\">{}<br>Scale <b>{}</b>{}; {} cases.</p>\n",
                   markup_escape(in.study_name), markup_escape(in.description), markup_escape(in.scale),
                   in.scale_description.empty() ? "" : ": " + markup_escape(in.scale_description), in.cases.size());

  h += "<h2>Findings</h2>\n<ul class=\"findings\">\n";
  for (const std::string& f : findings) h += "<li>" + markup_escape(f) + "</li>\n";
  h += "</ul>\n<p class=\"lead\">Computed from the metrics below, in the order the study lists its cases; changes "
       "within a quantity's resolution count as none (docs/study.md).</p>\n";

  h += "<h2>Maximum shear strain at the final displacement</h2>\n";
  if (has_panel) {
    h += fmt::format("<figure><a href=\"strain_panel.png\"><img src=\"strain_panel.png\" alt=\"Panel of maximum shear "
                     "strain maps, one per case\"></a><figcaption>Total maximum shear strain γ<sub>max</sub> (White &amp; "
                     "Bolton 2004) from the start of lowering, particles near the front window; one colour scale, 0 to "
                     "{:g} (the paper's Figure 7).</figcaption></figure>\n", vmax);
  } else {
    h += "<p class=\"note\">No case could be analysed.</p>\n";
  }

  h += fmt::format("<h2>Vertical displacement at δ = {}</h2>\n<div class=\"grid\">\n", markup_escape(contours_at));
  for (const StudyCaseResult& c : in.cases) {
    if (c.contour_analysis) {
      h += fmt::format("<figure><img src=\"{}\" alt=\"Vertical displacement contours of {}\"><figcaption>{}</figcaption>"
                       "</figure>\n", markup_escape(contour_file(c)), markup_escape(c.summary.label), markup_escape(c.summary.label));
    } else {
      h += fmt::format("<p class=\"note\">{}: {}</p>\n", markup_escape(c.summary.label), markup_escape(c.missing_note));
    }
  }
  h += "</div>\n";

  h += "<h2>Ground reaction curves</h2>\n<figure class=\"chart\"><img src=\"ground_reaction.png\" alt=\"Trapdoor "
       "stress against displacement, one curve per case\"><figcaption>The trapdoor's stress over its value before "
       "lowering (1: the dotted line) against its displacement over its width; the fall is the arching.</figcaption>"
       "</figure>\n";

  h += "<h2>Mechanism metrics</h2>\n<div class=\"scroll\"><table>\n<tr><th class=\"l\">case</th><th>δ/B</th>"
       "<th>band angle to the vertical (°) mean (left / right)</th><th>height reached / B</th><th>band width (d)</th>"
       "<th>zone at surface / B</th><th>zone at mid-height / B = shape ratio</th><th>shape</th><th>least trapdoor load</th>"
       "<th>at δ/B</th><th>final trapdoor load</th></tr>\n";
  for (const CaseSummary& s : summaries) {
    const double b = s.trapdoor_width;
    h += fmt::format("<tr><td class=\"l\">{}</td><td>{}</td><td>{} ({} / {})</td><td>{}</td><td>{}</td><td>{}</td>"
                     "<td>{}</td><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td></tr>\n",
                     markup_escape(s.label), cell(s.travel / b, "{:.2f}"), cell(s.band_angle_deg, "{:.1f}"),
                     cell(s.band_angle_left_deg, "{:.1f}"), cell(s.band_angle_right_deg, "{:.1f}"),
                     cell(s.band_height / b, "{:.2f}"), cell(s.band_width_d, "{:.1f}"), cell(s.zone_surface / b, "{:.2f}"),
                     cell(s.shape_ratio, "{:.2f}"), markup_escape(s.shape),
                     cell(s.min_load_ratio, "{:.3f}"), cell(s.min_load_at_over_b, "{:.3f}"),
                     cell(s.final_load_ratio, "{:.3f}"));
  }
  h += "</table></div>\n<p class=\"lead\">B: trapdoor width; d: mean particle diameter; loads over their value "
       "before lowering. Per-case details: each case's <code>analysis/metrics.json</code>; all of it: "
       "<a href=\"metrics.csv\">metrics.csv</a>, <a href=\"summary.json\">summary.json</a>.</p>\n";

  h += fmt::format("<h2>How large can the sinkhole get?</h2>\n<div class=\"scroll\"><table>\n<tr><th class=\"l\">case"
                   "</th><th>DEM surface zone, prototype (m)</th><th>class</th><th>supposition at {:g}° (m)</th><th>class"
                   "</th><th>angle of draw the DEM implies (°)</th></tr>\n", in.settings.angle_of_draw_deg);
  for (const CaseSummary& s : summaries) {
    h += fmt::format("<tr><td class=\"l\">{}</td><td>{}</td><td class=\"l\">{}</td><td>{}</td><td class=\"l\">{}</td>"
                     "<td>{}</td></tr>\n", markup_escape(s.label), cell(s.dem_surface_diameter, "{:.1f}"),
                     markup_escape(s.dem_size_class), cell(s.supposition_surface_diameter, "{:.1f}"),
                     markup_escape(s.supposition_size_class), cell(s.angle_from_surface_deg, "{:.1f}"));
  }
  h += "</table></div>\n<p class=\"lead\">Model lengths times the g level (centrifuge similitude); the supposition "
       "(Buttrick &amp; Van Schalkwyk 1995, SANS 1936) for the same throat and soil thickness, one layer. "
       "See docs/sinkhole.md for the method and its limits.</p>\n";

  h += "<h2>Parameters that differ</h2>\n";
  if (differences.empty()) {
    h += "<p>The cases' resolved configurations are identical apart from their names.</p>\n";
  } else {
    h += "<div class=\"scroll\"><table>\n<tr><th class=\"l\">key</th>";
    for (const CaseSummary& s : summaries) h += "<th>" + markup_escape(s.label) + "</th>";
    h += "</tr>\n";
    for (const ParameterDifference& d : differences) {
      h += "<tr><td class=\"l\"><code>" + markup_escape(d.key) + "</code></td>";
      for (const std::string& v : d.values) h += "<td>" + markup_escape(v) + "</td>";
      h += "</tr>\n";
    }
    h += "</table></div>\n";
  }

  h += "<h2>Runs</h2>\n<div class=\"scroll\"><table>\n<tr><th class=\"l\">case</th><th>particles</th><th>run time</th>"
       "<th>M particle-steps/s</th><th>segments</th><th class=\"l\">folder</th></tr>\n";
  for (const StudyCaseResult& c : in.cases) {
    const CaseCost& k = c.summary.cost;
    h += fmt::format("<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"l\"><code>{}"
                     "</code></td></tr>\n", markup_escape(c.summary.label), cell(k.particles, "{:.0f}"),
                     duration(k.wall_seconds), cell(k.particle_steps_per_second / 1e6, "{:.2f}"),
                     cell(k.segments, "{:.0f}"), markup_escape(c.run_dir.string()));
  }
  h += "</table></div>\n<p class=\"lead\">Run time: wall clock summed over the segments that ended (a first run and "
       "each resume); work lost to a killed segment is not counted.</p>\n";
  h += "</main>\n</body>\n</html>\n";

  const fs::path page = dir / "index.html";
  write_text_atomically(page, h);
  return page;
}

}  // namespace trapdem
