#include "study/study_report.hpp"

#include <cmath>
#include <functional>
#include <set>

#include <fmt/format.h>

#include "core/length_text.hpp"
#include "core/path_text.hpp"
#include "io/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/text_escape.hpp"
#include "plot/colour_map.hpp"
#include "plot/line_chart.hpp"
#include "plot/axes.hpp"
#include "plot/contour_plot.hpp"
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

// A figure of the report: its file in the report's format, and the image the page shows (the file
// itself, or a PNG beside a PDF: a browser does not show a PDF as an image).
struct ReportFigure {
  std::string file, shown;
};

ReportFigure report_figure(const std::string& stem, plot::FigureFormat format) {
  const std::string file = stem + plot::extension_of(format);
  return {file, format == plot::FigureFormat::pdf ? stem + ".png" : file};
}

// `draw` writes the figure to the path it is given: once in the report's format, once more as the
// page's PNG where that differs.
void write_figure(const fs::path& dir, const ReportFigure& f, const std::function<void(const fs::path&)>& draw,
                  std::set<std::string>& written) {
  draw(dir / f.file);
  if (f.shown != f.file) draw(dir / f.shown);
  written.insert(f.file);
  written.insert(f.shown);
}

// The figures a report of this folder drew before and this one did not (a case since analysed
// from its snapshots, renamed or dropped, another figure format) are removed: a stale
// run_shear_strain_rf1.png beside the page would be taken for this report's. Only the names the
// report gives its figures are touched; anything else a user put in the folder stays.
void remove_stale_figures(const fs::path& dir, const std::set<std::string>& written) {
  static const char* const stems[] = {"strain_panel", "contours_", "run_", "ground_reaction"};
  static const char* const extensions[] = {".png", ".svg", ".pdf"};
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (!e.is_regular_file() || written.count(name)) continue;
    const std::string extension = e.path().extension().string();
    bool figure_name = false;
    for (const char* x : extensions) figure_name = figure_name || extension == x;
    bool report_stem = false;
    for (const char* stem : stems) report_stem = report_stem || name.rfind(stem, 0) == 0;
    if (figure_name && report_stem) fs::remove(e.path(), ec);
  }
}

// The image on the page, linked to the figure's file.
std::string image_html(const ReportFigure& f, const std::string& alt) {
  return fmt::format("<a href=\"{}\"><img src=\"{}\" alt=\"{}\"></a>", markup_escape(f.file), markup_escape(f.shown),
                     markup_escape(alt));
}

std::string contour_stem(const StudyCaseResult& c) { return "contours_" + c.summary.name; }

// A run's own figure (StudyCaseResult::stored_*_figure) beside the page: its name there, e.g.
// "run_shear_strain_rf1.png" ("run_": the run's analysis drew it, not the report).
std::string stored_figure_name(const StudyCaseResult& c, const fs::path& figure) {
  return "run_" + figure.stem().string() + "_" + c.summary.name + figure.extension().string();
}

void copy_stored_figure(const fs::path& dir, const StudyCaseResult& c, const fs::path& figure,
                        std::set<std::string>& written) {
  if (figure.empty()) return;
  write_atomically(dir / stored_figure_name(c, figure), [&](const fs::path& temporary) {
    fs::copy_file(figure, temporary, fs::copy_options::overwrite_existing);
  });
  written.insert(stored_figure_name(c, figure));
}

// The page's figure of a run's own image (shown and linked as it is), its caption saying whose it is.
std::string stored_figure_html(const StudyCaseResult& c, const fs::path& figure, const std::string& alt,
                               const std::string& caption) {
  const std::string name = stored_figure_name(c, figure);
  return fmt::format("<figure>{}<figcaption>{}</figcaption></figure>\n", image_html({name, name}, alt), caption);
}

void write_ground_reaction_chart(const fs::path& path, const StudyReportInput& in) {
  plot::LineChart chart;
  chart.title = "Ground reaction curves";
  bool replicated = false;
  for (const StudyCaseResult& c : in.cases) replicated = replicated || c.ensemble.replicates.size() > 1;
  chart.subtitle = replicated ? "trapdoor stress σ over its value before lowering σ0; a case of several seeds: their mean"
                              : "trapdoor stress σ over its value before lowering σ0";
  chart.x_label = "trapdoor displacement δ/B (-)";
  chart.y_label = "trapdoor stress ratio σ/σ0 (-)";
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
  plot::write_line_chart(path, chart);
}

std::string replicate_chart_stem(const StudyCaseResult& c) { return "ground_reaction_" + c.summary.name; }

// A case's replicates' ground reaction curves (thin) with their mean (thick).
void write_replicate_chart(const fs::path& path, const StudyCaseResult& c) {
  plot::LineChart chart;
  chart.title = fmt::format("{}: ground reaction curves of {} packing seeds", c.summary.label,
                            c.ensemble.replicates.size());
  chart.subtitle = "each seed (thin) and their mean (thick, black)";
  chart.x_label = "trapdoor displacement δ/B (-)";
  chart.y_label = "trapdoor stress ratio σ/σ0 (-)";
  chart.reference_y = {1.0};
  for (std::size_t k = 0; k < c.ensemble.replicates.size(); ++k) {
    const CaseSummary& r = c.ensemble.replicates[k];
    plot::LineSeries series;
    series.name = fmt::format("seed {}", r.seed);
    series.colour = plot::series_colour(k);
    series.width = 1.0;
    series.x = r.grc_x_over_b;
    series.y = r.grc_trapdoor_ratio;
    chart.series.push_back(std::move(series));
  }
  plot::LineSeries mean;
  mean.name = "mean";
  mean.colour = {0.0, 0.0, 0.0};
  mean.width = 2.6;
  mean.x = c.summary.grc_x_over_b;
  mean.y = c.summary.grc_trapdoor_ratio;
  chart.series.push_back(std::move(mean));
  plot::write_line_chart(path, chart);
}

// A metric over a case's replicates for the page: "—" (none), the value (one), or the mean ± the
// sample standard deviation with the range below (several); "(n = k)" where fewer replicates than
// the case's measured it.
std::string spread_cell(const Spread& s, std::size_t runs, const char* format) {
  if (s.n == 0) return "—";
  const std::string missing = s.n < runs ? fmt::format(" (n = {})", s.n) : "";
  auto f = [&](double x) { return fmt::format(fmt::runtime(format), x); };
  if (!s.has_sd()) return f(s.mean) + missing;
  return fmt::format("{} ± {}<br><small>{}..{}{}</small>", f(s.mean), f(s.sd), f(s.min), f(s.max), missing);
}

// A band angle with its uncertainty: one run, ± the fit's standard error; several, ± the seeds'
// standard deviation (the range and the mean fit error below).
std::string angle_cell(const CaseEnsemble& e, double CaseSummary::*angle, double CaseSummary::*error) {
  const Spread a = e.spread(angle), err = e.spread(error);
  if (a.n == 0) return "—";
  const std::string missing = a.n < e.replicates.size() ? fmt::format(" (n = {})", a.n) : "";
  if (!a.has_sd())
    return err.n > 0 ? fmt::format("{:.1f} ± {:.1f}{}", a.mean, err.mean, missing) : fmt::format("{:.1f}{}", a.mean, missing);
  return fmt::format("{:.1f} ± {:.1f}<br><small>{:.1f}..{:.1f}, fit ± {:.1f}{}</small>", a.mean, a.sd, a.min, a.max,
                     err.mean, missing);
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

std::string metrics_csv(const StudyReportInput& in) {
  std::string out = "case,label,seed";
  for (const SummaryMetric& m : summary_metrics()) {
    out += ',';
    out += m.key;
  }
  out += ",shape,warnings,wall_seconds,particle_steps_per_second,particles\n";
  for (const StudyCaseResult& c : in.cases) {
    for (const StudyRunResult& run : c.runs) {
      CaseSummary s = run.summary;
      // The element test is the case's (one per case): on every row of it.
      s.phi_peak_deg = c.summary.phi_peak_deg;
      s.phi_cs_deg = c.summary.phi_cs_deg;
      // Appended piece by piece: `out += a + "," + b` trips GCC 12's false -Wrestrict (GCC bug 105651).
      out += csv_field(s.name);
      out += ',';
      out += csv_field(s.label);
      out += ',';
      if (s.replicate) out += std::to_string(s.seed);
      for (const SummaryMetric& m : summary_metrics()) {
        out += ',';
        out += csv_number(s.*m.field);
      }
      out += ',';
      out += csv_field(s.shape);
      out += ',';
      out += std::to_string(s.warnings.size());
      for (double x : {s.cost.wall_seconds, s.cost.particle_steps_per_second, s.cost.particles}) {
        out += ',';
        out += csv_number(x);
      }
      out += '\n';
    }
  }
  return out;
}

// The spread of one metric of a case: the element angles are the case's own (one test), the
// others over its analysed replicates.
static Spread case_metric_spread(const StudyCaseResult& c, double CaseSummary::*field) {
  if (field == &CaseSummary::phi_peak_deg || field == &CaseSummary::phi_cs_deg) return spread_of({c.summary.*field});
  return c.ensemble.spread(field);
}

std::string case_summary_csv(const StudyReportInput& in) {
  std::string out = "case,label,metric,n,mean,sd,min,max\n";
  for (const StudyCaseResult& c : in.cases) {
    for (const SummaryMetric& m : summary_metrics()) {
      const Spread s = case_metric_spread(c, m.field);
      out += fmt::format("{},{},{},{},{},{},{},{}\n", csv_field(c.summary.name), csv_field(c.summary.label), m.key, s.n,
                         csv_number(s.mean), csv_number(s.sd), csv_number(s.min), csv_number(s.max));
    }
  }
  return out;
}

fs::path write_study_report(const fs::path& dir, const StudyReportInput& in) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) throw FileError(fmt::format("cannot create the report folder {}: {}", dir.string(), ec.message()));

  // Figures first: the page never points at an image that is not there.
  std::set<std::string> written;  // the figures' file names
  // The panel: each case's analysis, or its stored map where its runs' snapshots are gone.
  std::vector<plot::StrainPanelMap> finals;
  std::vector<std::string> panel_titles;  // the case labels
  bool stored_in_panel = false;
  for (const StudyCaseResult& c : in.cases) {
    if (c.final_analysis) {
      finals.push_back({c.final_analysis, nullptr});
    } else if (c.stored_strain_map) {
      finals.push_back({nullptr, c.stored_strain_map.get()});
      stored_in_panel = true;
    } else {
      continue;
    }
    panel_titles.push_back(c.summary.label);
  }
  double vmax = in.settings.max_strain;
  if (!(vmax > 0.0))
    for (const plot::StrainPanelMap& m : finals)
      vmax = std::max(vmax, m.analysis ? plot::auto_strain_scale(*m.analysis) : plot::auto_strain_scale(*m.stored));
  const bool has_panel = !finals.empty();
  const ReportFigure panel = report_figure("strain_panel", in.format);
  if (has_panel)
    write_figure(dir, panel, [&](const fs::path& p) { plot::write_strain_panel_of_maps(p, finals, panel_titles, vmax); },
                 written);
  // The contour figures on one scale: the colours span +-the trapdoor's displacement (the same for
  // every case at report.contours_at), the lines at one step for every case (not each figure's own
  // automatic levels, which would differ with each field's range).
  double contour_travel = 0.0;  // m
  for (const StudyCaseResult& c : in.cases)
    if (c.contour_analysis) contour_travel = std::max(contour_travel, c.contour_analysis->trapdoor_travel());
  const plot::ContourLevels contour_step{{}, contour_travel > 0.0 ? plot::nice_step(contour_travel, 8) : 0.0};
  for (const StudyCaseResult& c : in.cases)
    if (c.contour_analysis)
      write_figure(dir, report_figure(contour_stem(c), in.format),
                   [&](const fs::path& p) { plot::write_displacement_contours(p, *c.contour_analysis, contour_step); },
                   written);
  for (const StudyCaseResult& c : in.cases) {
    copy_stored_figure(dir, c, c.stored_strain_figure, written);
    copy_stored_figure(dir, c, c.stored_displacement_figure, written);
  }
  const ReportFigure ground_reaction = report_figure("ground_reaction", in.format);
  write_figure(dir, ground_reaction, [&](const fs::path& p) { write_ground_reaction_chart(p, in); }, written);
  for (const StudyCaseResult& c : in.cases)
    if (c.ensemble.replicates.size() > 1)
      write_figure(dir, report_figure(replicate_chart_stem(c), in.format),
                   [&](const fs::path& p) { write_replicate_chart(p, c); }, written);

  remove_stale_figures(dir, written);

  std::vector<CaseSummary> summaries;
  std::vector<CaseEnsemble> ensembles;
  std::vector<std::vector<std::pair<std::string, std::string>>> parameters;
  bool replicated = false;
  for (const StudyCaseResult& c : in.cases) {
    summaries.push_back(c.summary);
    ensembles.push_back(c.ensemble);
    parameters.push_back(c.parameters);
    replicated = replicated || c.runs.size() > 1;
  }
  const std::vector<std::string> findings = study_findings(ensembles, in.settings.angle_of_draw_deg);
  const std::vector<ParameterDifference> differences = differing_parameters(parameters);

  Json summary = Json::object();
  summary.set("study", in.study_name);
  summary.set("scale", in.scale);
  Json cases = Json::array();
  for (const StudyCaseResult& c : in.cases) {
    // The case's values (the replicates' means), its spreads and each run.
    Json j = to_json(c.summary);
    j.set("n", static_cast<double>(c.ensemble.replicates.size()));
    Json spreads = Json::object();
    for (const SummaryMetric& m : summary_metrics()) spreads.set(m.key, to_json(case_metric_spread(c, m.field)));
    j.set("spread", spreads);
    Json runs = Json::array();
    for (const StudyRunResult& r : c.runs) {
      // Each run's measured values (its cost and folder are in metrics.csv and on the page: the
      // numbers here stay the same for the same runs wherever and however fast they ran).
      const Json all = to_json(r.summary);  // named: a temporary's members() would dangle in the loop
      Json run = Json::object();
      for (const auto& [key, value] : all.members())
        if (key != "cost") run.set(key, value);
      run.set("analysed", r.analysed);
      runs.push_back(run);
    }
    j.set("runs", runs);
    if (std::isfinite(c.element_confining)) j.set("element_confining_Pa", c.element_confining);
    cases.push_back(j);
  }
  summary.set("cases", cases);
  summary.set("spread_statistic", "sample standard deviation (n - 1) over each case's analysed runs, and min..max");
  Json finding_list = Json::array();
  for (const std::string& f : findings) finding_list.push_back(f);
  summary.set("findings", finding_list);
  summary.set("strain_scale_max", vmax);
  write_text_atomically(dir / "summary.json", summary.dump() + "\n");
  write_text_atomically(dir / "metrics.csv", metrics_csv(in));
  write_text_atomically(dir / "case_summary.csv", case_summary_csv(in));

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
       "within a quantity's resolution, or within the sum of two cases' seed-to-seed standard deviations, count as "
       "none (docs/study.md).</p>\n";

  h += "<h2>Maximum shear strain at the final displacement</h2>\n";
  if (has_panel) {
    h += fmt::format("<figure>{}<figcaption>Total maximum shear strain γ<sub>max</sub> (White &amp; "
                     "Bolton 2004) from the start of lowering, particles near the front window; one colour scale, 0 to "
                     "{:g} (the paper's Figure 7).{}</figcaption></figure>\n",
                     image_html(panel, "Panel of maximum shear strain maps, one per case"), vmax,
                     stored_in_panel ? " A map marked “stored grid” is of a run whose snapshots are gone, drawn from its "
                                       "analysis/field_history.h5: the same triangles sampled once per mean diameter, "
                                       "smoothed as the analysis smooths them."
                                     : "");
  } else {
    h += "<p class=\"note\">No case has a figure the report could draw.</p>\n";
  }
  bool stored_maps = false;
  for (const StudyCaseResult& c : in.cases)
    stored_maps = stored_maps || (!c.final_analysis && !c.stored_strain_figure.empty());
  if (stored_maps) h += "<div class=\"grid\">\n";
  for (const StudyCaseResult& c : in.cases)  // the cases left out of the panel: their own figure, or why not
    if (!c.final_analysis && !c.stored_strain_figure.empty())
      h += stored_figure_html(c, c.stored_strain_figure, "Maximum shear strain map of " + c.summary.label,
                              fmt::format("{}: the map its run's own analysis drew, on that figure's colour scale "
                                          "(not the panel's), at the triangles' resolution. {}",
                                          markup_escape(c.summary.label), markup_escape(c.missing_note)));
  if (stored_maps) h += "</div>\n";
  for (const StudyCaseResult& c : in.cases)
    if (!c.final_analysis && c.stored_strain_figure.empty())
      h += fmt::format("<p class=\"note\">{}: {}</p>\n", markup_escape(c.summary.label), markup_escape(c.missing_note));

  h += fmt::format("<h2>Vertical displacement at δ = {}</h2>\n", markup_escape(contours_at));
  if (contour_step.step > 0.0)
    h += fmt::format("<p class=\"lead\">One scale for every case: the colours span settlement −δ to +δ (the trapdoor's "
                     "displacement, {}), the contour lines every {}.</p>\n",
                     markup_escape(format_mm(contour_travel)), markup_escape(format_mm(contour_step.step)));
  h += "<div class=\"grid\">\n";
  for (const StudyCaseResult& c : in.cases) {
    if (c.contour_analysis) {
      h += fmt::format("<figure>{}<figcaption>{}</figcaption></figure>\n",
                       image_html(report_figure(contour_stem(c), in.format),
                                  "Vertical displacement contours of " + c.summary.label),
                       markup_escape(c.summary.label));
    } else if (!c.stored_displacement_figure.empty()) {
      h += stored_figure_html(c, c.stored_displacement_figure, "Vertical displacement contours of " + c.summary.label,
                              fmt::format("{}: the contours its run's own analysis drew, at the end of lowering "
                                          "(not at δ = {}). {}",
                                          markup_escape(c.summary.label), markup_escape(contours_at),
                                          markup_escape(c.missing_note)));
    } else {
      h += fmt::format("<p class=\"note\">{}: {}</p>\n", markup_escape(c.summary.label), markup_escape(c.missing_note));
    }
  }
  h += "</div>\n";

  h += fmt::format("<h2>Ground reaction curves</h2>\n<figure class=\"chart\">{}<figcaption>The trapdoor's stress over "
                   "its value before lowering (1: the dotted line) against its displacement over its width; the fall is "
                   "the arching.</figcaption></figure>\n",
                   image_html(ground_reaction, "Trapdoor stress against displacement, one curve per case"));
  for (const StudyCaseResult& c : in.cases) {
    if (c.ensemble.replicates.size() < 2) continue;
    h += fmt::format("<figure class=\"chart\">{}<figcaption>{}: each packing seed and their mean.</figcaption></figure>\n",
                     image_html(report_figure(replicate_chart_stem(c), in.format),
                                "Ground reaction curves of the seeds of " + c.summary.label),
                     markup_escape(c.summary.label));
  }

  const bool element = in.settings.element_test;
  h += "<h2>Mechanism metrics</h2>\n<div class=\"scroll\"><table>\n<tr><th class=\"l\">case</th><th>runs (n)</th>"
       "<th>δ/B</th><th>band angle to the vertical (°), mean</th><th>left</th><th>right</th><th>height reached / B</th>"
       "<th>band width (d)</th><th>zone at surface / B</th><th>zone at mid-height / B = shape ratio</th><th>shape</th>"
       "<th>least trapdoor load</th><th>at δ/B</th><th>final trapdoor load</th>";
  if (element) h += "<th>φ'<sub>peak</sub> (°)</th><th>φ'<sub>cs</sub> (°)</th>";
  h += "<th>warnings</th></tr>\n";
  for (const StudyCaseResult& c : in.cases) {
    const CaseEnsemble& e = c.ensemble;
    const std::size_t n = e.replicates.size();
    auto over_b = [&](double CaseSummary::*field) {
      return e.spread([field](const CaseSummary& r) { return r.*field / r.trapdoor_width; });
    };
    std::size_t warnings = 0;
    for (const CaseSummary& r : e.replicates) warnings += r.warnings.empty() ? 0 : 1;
    h += fmt::format("<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
                     "<td>{}</td><td>{}</td><td>{}</td><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td>",
                     markup_escape(c.summary.label), n == 1 ? "n = 1" : fmt::format("{}", n),
                     spread_cell(over_b(&CaseSummary::travel), n, "{:.2f}"),
                     angle_cell(e, &CaseSummary::band_angle_deg, &CaseSummary::band_angle_error_deg),
                     angle_cell(e, &CaseSummary::band_angle_left_deg, &CaseSummary::band_angle_left_error_deg),
                     angle_cell(e, &CaseSummary::band_angle_right_deg, &CaseSummary::band_angle_right_error_deg),
                     spread_cell(over_b(&CaseSummary::band_height), n, "{:.2f}"),
                     spread_cell(e.spread(&CaseSummary::band_width_d), n, "{:.1f}"),
                     spread_cell(over_b(&CaseSummary::zone_surface), n, "{:.2f}"),
                     spread_cell(e.spread(&CaseSummary::shape_ratio), n, "{:.2f}"), markup_escape(c.summary.shape),
                     spread_cell(e.spread(&CaseSummary::min_load_ratio), n, "{:.3f}"),
                     spread_cell(e.spread(&CaseSummary::min_load_at_over_b), n, "{:.3f}"),
                     spread_cell(e.spread(&CaseSummary::final_load_ratio), n, "{:.3f}"));
    if (element)
      h += fmt::format("<td>{}</td><td>{}</td>", cell(c.summary.phi_peak_deg, "{:.1f}"), cell(c.summary.phi_cs_deg, "{:.1f}"));
    h += fmt::format("<td>{}</td></tr>\n", warnings == 0 ? "—" : fmt::format("{} of {} runs (see Findings)", warnings, n));
  }
  h += "</table></div>\n<p class=\"lead\">B: trapdoor width; d: mean particle diameter; loads over their value "
       "before lowering. A case of several packing seeds: mean ± sample standard deviation, the range min..max "
       "below; (n = k): measured in k of its runs. Band angles: one run ± the standard error of the trace's fit; "
       "several ± the seeds' standard deviation, with the mean fit error."
       + std::string(element ? " φ': the case's virtual element test (one per case, cases/&lt;name&gt;/element/, "
                               "docs/element.md); the seed's glass beads: 16.8° / 15.7°." : "") +
       " Per-run details: each run's <code>analysis/metrics.json</code>; every run: <a href=\"metrics.csv\">metrics.csv"
       "</a>; each case's mean, sd, min, max and n: <a href=\"case_summary.csv\">case_summary.csv</a>, "
       "<a href=\"summary.json\">summary.json</a>.</p>\n";

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

  h += "<h2>Runs</h2>\n<div class=\"scroll\"><table>\n<tr><th class=\"l\">case</th><th>seed</th><th>particles</th>"
       "<th>run time</th><th>M particle-steps/s</th><th>segments</th><th class=\"l\">folder</th></tr>\n";
  const fs::path study_dir = dir.parent_path();  // the report is the study folder's report/
  for (const StudyCaseResult& c : in.cases) {
    for (const StudyRunResult& r : c.runs) {
      const CaseCost& k = r.summary.cost;
      h += fmt::format("<tr><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td>"
                       "<td class=\"l\"><code>{}</code>{}</td></tr>\n", markup_escape(c.summary.label),
                       r.summary.replicate ? std::to_string(r.summary.seed) : "its own", cell(k.particles, "{:.0f}"),
                       duration(k.wall_seconds), cell(k.particle_steps_per_second / 1e6, "{:.2f}"),
                       cell(k.segments, "{:.0f}"), markup_escape(path_from(r.run_dir, study_dir)),
                       r.missing_note.empty() ? "" : " <span class=\"note\">" + markup_escape(r.missing_note) + "</span>");
    }
  }
  h += "</table></div>\n<p class=\"lead\">Run time: wall clock summed over the segments that ended (a first run and "
       "each resume); work lost to a killed segment is not counted.</p>\n";
  h += "</main>\n</body>\n</html>\n";

  const fs::path page = dir / "index.html";
  write_text_atomically(page, h);
  return page;
}

}  // namespace trapdem
