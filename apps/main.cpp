// trapdem: the command line. Each subcommand is one stage of the work, from packing to figures.
#include <algorithm>
#include <charconv>
#include <cmath>
#include <exception>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "analyze_command.hpp"
#include "calibrate_command.hpp"
#include "compare_command.hpp"
#include "core/errors.hpp"
#include "core/exit_codes.hpp"
#include "core/nearest_name.hpp"
#include "core/thread_count.hpp"
#include "core/wait_policy.hpp"
#include "deposit_command.hpp"
#include "element_command.hpp"
#include "piv_command.hpp"
#include "run_command.hpp"
#include "showcase.hpp"
#include "sinkhole_command.hpp"
#include "study_command.hpp"

namespace {

// --submit and the Slurm options of `study` and `calibrate`: --partition, --time, --cpus-per-task
// and --sbatch-arg need --submit.
void add_submit_options(CLI::App& command, trapdem::app::SubmitOptions& o) {
  auto* submit = command.add_option("--submit", o.submit,
                                    "slurm: submit the runs not finished as a Slurm job array and the report as a job "
                                    "after it (docs/study.md, On a cluster)")
                     ->check(CLI::IsMember({"slurm"}));
  command.add_option("--partition", o.slurm.partition, "With --submit: the Slurm partition (default: the cluster's)")
      ->needs(submit);
  command.add_option("--time", o.slurm.time, "With --submit: each task's time limit, e.g. 12:00:00 or 2-00:00:00")
      ->needs(submit);
  command.add_option("--cpus-per-task", o.slurm.cpus_per_task, "With --submit: CPUs (threads) of each run (default 1)")
      ->needs(submit);
  command.add_option("--sbatch-arg", o.slurm.sbatch_args,
                     "With --submit: another sbatch option for both jobs, e.g. --sbatch-arg=--account=geo (repeatable)")
      ->needs(submit)
      ->allow_extra_args(false);
}

// The first word that is not an option must name a command: `trapdem NOSUCH` (with or without
// --help) is refused with the word and the nearest command, not CLI11's "A subcommand is required"
// (or the main help and exit 0, which let a script with a typo succeed). "" when it does.
std::string unknown_command_message(const CLI::App& app, int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.empty() || word[0] == '-') continue;  // the only options before a command are --help's
    std::vector<std::string> commands;
    for (const CLI::App* command : app.get_subcommands([](const CLI::App*) { return true; }))
      commands.push_back(command->get_name());
    if (std::find(commands.begin(), commands.end(), word) != commands.end()) return "";
    std::string message = fmt::format("trapdem: input error: '{}' is not a trapdem command", word);
    const std::string nearest = trapdem::nearest_name(word, commands);
    if (!nearest.empty()) return message + fmt::format(" (did you mean {}?)", nearest);
    return message + fmt::format(" (the commands: {})", fmt::join(commands, ", "));
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  // Before anything starts a thread: on a crowded host, threads that sleep while they wait (this
  // may re-execute the program; src/core/wait_policy.hpp).
  trapdem::wait_passively_when_crowded(argc, argv);
  CLI::App app{"trapdem: trapdoor experiments with the discrete element method"};
  // Every --threads: 0 (all cores) up to trapdem::kMaxThreads, with a message that says so (CLI11's
  // NonNegativeNumber printed a 309-digit bound for "abc" and let 100000 through to libgomp).
  const CLI::Validator thread_count(
      [](std::string& text) -> std::string {
        try {
          trapdem::parse_thread_count(text, "--threads");
          return {};
        } catch (const trapdem::InputError& e) {
          return e.what();
        }
      },
      fmt::format("0..{}", trapdem::kMaxThreads), "thread count");
  // A finite number in [lo, hi] (or (lo, hi] when lo is excluded), said in words for any other text.
  auto number_in = [](double lo, double hi, bool lo_included, const char* unit) {
    const std::string expected =
        fmt::format("expected a number {} {:g} and <= {:g}{}", lo_included ? ">=" : ">", lo, hi, unit);
    return CLI::Validator(
        [=](std::string& text) -> std::string {
          double x = 0.0;
          const char* end = text.data() + text.size();
          const auto [ptr, ec] = std::from_chars(text.data(), end, x);
          const bool ok = ec == std::errc() && ptr == end && std::isfinite(x) && (lo_included ? x >= lo : x > lo) && x <= hi;
          return ok ? std::string() : fmt::format("'{}': {}", text, expected);
        },
        expected, "bounded number");
  };
  app.require_subcommand(1);

  trapdem::app::RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run a trapdoor experiment: pluviation, settling, spin-up, lowering");
  run_cmd->add_option("config", run.config_file, "Configuration file (TOML); default: the demo preset")
      ->check(CLI::ExistingFile);
  run_cmd->add_option("--preset", run.preset, "Run a preset (see `trapdem presets`)");
  run_cmd->add_option("--out", run.out_dir, "Output folder (default: ./trapdem-out/<name>)");
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (default: numerics.threads, else all cores)")
      ->check(thread_count);
  run_cmd->add_option("--set", run.overrides, "Override a key: --set trapdoor.rate=0.1 (repeatable)");
  run_cmd->add_option("--resume", run.resume_dir, "Carry on the run in this folder from its checkpoint")
      ->check(CLI::ExistingDirectory);
  run_cmd->add_option("--allow-change", run.allowed_changes,
                      "With --resume: KEY may differ from the run that was started (--set KEY=..., or an edited "
                      "resolved.toml); logged in run.log and resolved.toml (repeatable)");
  run_cmd->add_flag("--quiet", run.quiet, "No progress lines on the terminal (run.log keeps them)");
  run_cmd->add_option("--stop-after", run.stop_after_seconds,
                      "Stop with a checkpoint after this many seconds of wall clock");

  auto* presets_cmd = app.add_subcommand("presets", "List the presets, one line each");

  trapdem::app::ShowcaseOptions showcase;
  auto* sc = app.add_subcommand("showcase", "A packing settles in a box under gravity; prints speed and floor load");
  sc->add_option("--particles", showcase.particles, "Number of spheres")->check(number_in(0, 1e8, false, ""));
  sc->add_option("--threads", showcase.threads, "OpenMP threads (default: all cores)")->check(thread_count);

  trapdem::AnalyzeOptions analyze;
  auto* an = app.add_subcommand("analyze", "Strain fields, shear bands and zone of influence of a run; writes DIR/analysis/");
  an->add_option("dir", analyze.dir, "Run folder (snapshots.h5, resolved.toml, trapdoor.csv)")->required();
  an->add_option("--at", analyze.at, "Trapdoor displacement to analyse, e.g. 80mm (default: the last snapshot)");
  an->add_option("--reference", analyze.reference, "Reference trapdoor displacement (default 0mm)");
  an->add_option("--view", analyze.view, "front: particles near the glass; all: every particle")
      ->check(CLI::IsMember({"front", "all"}));
  an->add_option("--front-depth", analyze.front_depth, "Front view depth from the glass (default 1.5 max diameters)");
  an->add_flag("--incremental", analyze.incremental, "Also accumulate incremental strain over the snapshots between");
  an->add_option("--grid", analyze.grid, "Grid spacing of the vertical displacement, e.g. 2mm (default d/2)");
  an->add_option("--smoothing", analyze.smoothing, "Strain smoothing (Gaussian) for band tracing and the strain map, in mean diameters (default 2; 0: none)")->check(number_in(0, 100, true, " mean diameters"));
  an->add_option("--dumps", analyze.dumps, "LAMMPS/LIGGGHTS text dumps (id x y z radius) instead of snapshots.h5");
  an->add_option("--displacements", analyze.displacements, "Trapdoor displacement of each dump: 0mm,10mm,...");
  an->add_option("--config", analyze.config, "Geometry (TOML with [box], [trapdoor]; default DIR/resolved.toml)");
  an->add_option("--out", analyze.out, "Output folder (default DIR/analysis)");
  an->add_flag("--no-figures", analyze.no_figures, "Fields and metrics only");
  an->add_flag("--no-field-history", analyze.no_field_history,
              "No field_history.h5 (every snapshot's settlement and strain on one grid)");
  an->add_option("--field-history-grid", analyze.field_history_grid,
                 "Grid spacing of field_history.h5, e.g. 2mm (default: one mean diameter)");
  an->add_option("--format", analyze.format, "Figure format: png (default), svg or pdf")
      ->check(CLI::IsMember({"png", "svg", "pdf"}, CLI::ignore_case));
  auto* an_levels = an->add_option("--contour-levels", analyze.contour_levels,
                                   "Settlement contour levels, e.g. 0.5mm,1mm,2mm (default: automatic)");
  an->add_option("--contour-step", analyze.contour_step, "Settlement contour step, e.g. 1mm")->excludes(an_levels);
  an->add_flag("--quiet", analyze.quiet, "No metrics table on the terminal");

  trapdem::app::FigureOptions figure;
  auto* fig = app.add_subcommand("figure", "Panel of several runs' shear strain maps with one colour scale, or (--grc) their ground reaction curves");
  fig->add_option("dirs", figure.dirs, "Run folders")->required();
  fig->add_option("--out", figure.out, "Figure file; .png, .svg or .pdf picks the format (default panel.png, grc.png with --grc)");
  fig->add_flag("--grc", figure.grc, "The runs' ground reaction curves (trapdoor.csv) on one chart");
  fig->add_option("--labels", figure.panel.labels, "Panel titles / legend entries, one per run (default: the runs' names)")
      ->delimiter(',');
  fig->add_option("--at", figure.panel.at, "Trapdoor displacement, e.g. 80mm (default: each run's last snapshot)");
  fig->add_option("--reference", figure.panel.reference, "Reference trapdoor displacement (default 0mm)");
  fig->add_option("--view", figure.panel.view, "front or all")->check(CLI::IsMember({"front", "all"}));
  fig->add_option("--front-depth", figure.panel.front_depth, "Front view depth from the glass");
  fig->add_option("--max-strain", figure.panel.max_strain, "Top of the gamma_max colour scale (default: automatic)");

  trapdem::app::SinkholeOptions sinkhole;
  auto* sink = app.add_subcommand("sinkhole", "Maximum sinkhole size by scenario supposition (SANS 1936); --from DIR: beside a DEM run's");
  sink->add_option("--throat", sinkhole.throat, "Cavity throat diameter, e.g. 2.5 or 2.5m");
  sink->add_option("--layer", sinkhole.layers,
                   "Blanket layer THICKNESS:ANGLE_OF_DRAW (m, degrees from the vertical), cavity upward (repeatable); "
                   "with --from: :ANGLE only")
      ->allow_extra_args(false);
  sink->add_option("--from", sinkhole.from, "DEM run folder analysed by `trapdem analyze` (analysis/metrics.json)");
  sink->add_flag("--json", sinkhole.json, "JSON on stdout instead of the table");

  trapdem::app::PivOptions piv;
  auto* piv_cmd = app.add_subcommand("piv", "PIV of a photograph sequence: displacements, strain, figures (docs/piv.md)");
  piv_cmd->add_option("images", piv.images, "Images in order (any format OpenCV reads)")->required();
  piv_cmd->add_option("--out", piv.out, "Output folder")->required();
  piv_cmd->add_option("--subset", piv.subset, "Subset side, px (default 32)");
  piv_cmd->add_option("--step", piv.step, "Spacing of subset centres, px (default 16)");
  piv_cmd->add_option("--roi", piv.roi, "Region of interest x0,y0,x1,y1 in px of image 1 (default: whole image)");
  auto* piv_scale = piv_cmd->add_option("--scale", piv.scale, "mm per px: model coordinates x right, z up");
  piv_cmd->add_option("--origin", piv.origin, "With --scale: model coordinates X,Z (mm) of pixel (0,0) (default 0,0)");
  piv_cmd->add_option("--control-points", piv.control_points, "CSV x_px,y_px,x_model,z_model: fit to model coordinates")
      ->excludes(piv_scale);
  piv_cmd->add_option("--fit", piv.fit, "Control point fit: affine or projective (default)")
      ->check(CLI::IsMember({"affine", "projective"}));
  piv_cmd->add_option("--threads", piv.threads, "OpenMP threads (default: all cores)")->check(thread_count);
  piv_cmd->add_flag("--no-figures", piv.no_figures, "Displacements, piv.h5 and strain only");
  piv_cmd->add_option("--format", piv.format, "Figure format: png (default), svg or pdf")
      ->check(CLI::IsMember({"png", "svg", "pdf"}, CLI::ignore_case));
  auto* piv_levels = piv_cmd->add_option("--contour-levels", piv.contour_levels,
                                         "Settlement contour levels in the plot unit (mm with --scale), e.g. 0.5,1,2");
  piv_cmd->add_option("--contour-step", piv.contour_step, "Settlement contour step in the plot unit, e.g. 1")
      ->excludes(piv_levels);
  piv_cmd->add_flag("--quiet", piv.quiet, "No progress lines");

  trapdem::app::SynthOptions synth;
  auto* synth_cmd = app.add_subcommand("synth", "Synthetic speckle images under a known displacement field, with truth.csv");
  synth_cmd->add_option("--field", synth.field, "rigid, strain, shear or trapdoor")
      ->check(CLI::IsMember({"rigid", "strain", "shear", "trapdoor"}));
  synth_cmd->add_option("--out", synth.out, "Output folder")->required();
  synth_cmd->add_option("--size", synth.size, "WIDTHxHEIGHT px (default 512x512)");
  synth_cmd->add_option("--images", synth.images, "Images including the undeformed first (default 2)");
  synth_cmd->add_option("--noise", synth.noise, "Gaussian noise, grey levels (default 2)");
  synth_cmd->add_option("--magnitude", synth.magnitude,
                        "Last image: shift px (rigid; v = 0.6 u), strain (strain: exx = -eyy), gamma (shear), settlement px (trapdoor)");
  synth_cmd->add_option("--seed", synth.seed, "Random seed (default 1)");

  trapdem::app::RenderOptions render;
  auto* render_cmd = app.add_subcommand("render", "DEM snapshots as the camera sees them through the front window (PNGs)");
  render_cmd->add_option("dir", render.dir, "Run folder (snapshots.h5, resolved.toml)")->required();
  render_cmd->add_option("--out", render.out, "Output folder (default DIR/camera)");
  render_cmd->add_option("--px-per-mm", render.px_per_mm, "Image scale (default 4)")->check(number_in(0, 1000, false, " px per mm"));
  render_cmd->add_option("--config", render.config, "Geometry (default DIR/resolved.toml)");
  render_cmd->add_flag("--check", render.check, "Run PIV on the images and compare with the particle displacements");
  render_cmd->add_option("--subset", render.subset, "--check subset size, px (default about 3 diameters)");
  render_cmd->add_option("--threads", render.threads, "OpenMP threads for --check")->check(thread_count);

  trapdem::CompareOptions compare;
  auto* cmp_cmd = app.add_subcommand("compare", "DEM against PIV: vertical displacement on one grid, RMS error, overlay figure");
  cmp_cmd->add_option("dem_dir", compare.dem_dir, "DEM run folder (resolved.toml, snapshots.h5)")->required();
  cmp_cmd->add_option("piv_dir", compare.piv_dir, "PIV output folder (piv.h5 with model coordinates)")->required();
  cmp_cmd->add_option("--at", compare.at, "Trapdoor displacement to compare, e.g. 10mm")->required();
  cmp_cmd->add_option("--grid", compare.grid, "Spacing of the common grid (default 2mm)");
  cmp_cmd->add_option("--image", compare.image, "PIV image (1-based; default: the one rendered from the DEM snapshot)");
  cmp_cmd->add_option("--reference-image", compare.reference_image,
                      "PIV image at the start of lowering (default: rendered from the DEM reference, else 1)");
  cmp_cmd->add_option("--piv-trapdoor", compare.piv_trapdoor,
                      "Trapdoor centre X,Z in the PIV model coordinates, e.g. 125mm,0mm (default: the DEM box's)");
  cmp_cmd->add_option("--out", compare.out, "Figure (default DEM_DIR/analysis/compare_<at>mm.png)");
  cmp_cmd->add_flag("--no-figure", compare.no_figure, "Numbers only");
  cmp_cmd->add_flag("--json", compare.json, "JSON on stdout instead of the text");

  trapdem::app::StudyOptions study;
  auto* study_cmd = app.add_subcommand("study", "Run a study's cases (resumable) and write DIR/report/index.html");
  study_cmd->add_option("file", study.file, "Study file (TOML; see studies/ and docs/study.md)")
      ->required()->check(CLI::ExistingFile);
  study_cmd->add_option("--out", study.out, "Study folder (default trapdem-out/<study>-<scale>)");
  study_cmd->add_option("--scale", study.scale, "One of the study's scales, e.g. demo or paper (default: its default_scale)");
  study_cmd->add_option("--threads", study.threads, "OpenMP threads per run (default: all cores)")
      ->check(thread_count);
  study_cmd->add_flag("--quiet", study.quiet, "Runs' progress lines only in their run.log");
  study_cmd->add_flag("--report-only", study.report_only, "Run nothing: report on the finished cases");
  study_cmd->add_flag("--collect", study.collect, "No trapdoor run: the element tests still missing, then the report (a Slurm submission's report job)");
  study_cmd->add_flag("--status", study.status, "Run nothing: where each run stands (not started, running, finished, failed)");
  study_cmd->add_option("--stop-after", study.stop_after_seconds,
                        "Stop with the running case's checkpoint after this many seconds of wall clock, counted "
                        "from the first run's start; no run starts after it (the same command carries on)")
      ->check(CLI::PositiveNumber);
  study_cmd->add_option("--case", study.cases,
                        "Run only this case's runs (repeatable); the others are left as they are, the report "
                        "covers every finished run");
  study_cmd->add_option("--seed", study.seeds,
                        "Run only the runs with this packing seed (repeatable; a replicate scale's seeds)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            const bool digits = !text.empty() && text.size() <= 19 &&
                                text.find_first_not_of("0123456789") == std::string::npos;
            return digits ? std::string() : "expected a packing seed, an integer >= 0, not '" + text + "'";
          },
          "SEED"));
  study_cmd->add_option("--format", study.format, "Figure format of the report and the runs' analyses: png (default), svg or pdf")->check(CLI::IsMember({"png", "svg", "pdf"}, CLI::ignore_case));
  add_submit_options(*study_cmd, study.submit);

  trapdem::app::CalibrateCommand calibrate_command;
  trapdem::CalibrateOptions& calibrate = calibrate_command.calibrate;
  auto* cal = app.add_subcommand("calibrate", "Run a parameter grid as a study and rank it against PIV (compare)");
  cal->add_option("base", calibrate.base, "Configuration file (TOML) the grid varies")->required()->check(CLI::ExistingFile);
  cal->add_option("--vary", calibrate.vary, "KEY=V1,V2,... (repeatable; every combination runs)")->required();
  cal->add_option("--target", calibrate.target, "PIV folder (piv.h5 in model coordinates)")->required();
  cal->add_option("--at", calibrate.at, "Trapdoor displacement to compare, e.g. 10mm")->required();
  cal->add_option("--out", calibrate.out, "Folder (default trapdem-out/calibrate-<base name>)");
  cal->add_option("--grid", calibrate.grid, "Spacing of the common grid (default 2mm)");
  cal->add_option("--piv-trapdoor", calibrate.piv_trapdoor, "Trapdoor centre X,Z in the PIV coordinates (see compare)");
  cal->add_option("--threads", calibrate.threads, "OpenMP threads per run (default: all cores)")
      ->check(thread_count);
  cal->add_flag("--quiet", calibrate.quiet, "Runs' progress lines only in their run.log");
  cal->add_flag("--collect", calibrate.collect, "Run nothing: rank the grid once every case has finished (a Slurm submission's report job)");
  cal->add_flag("--status", calibrate_command.status, "Run nothing: where each case stands");
  cal->add_option("--format", calibrate.format, "Figure format: png (default), svg or pdf")->check(CLI::IsMember({"png", "svg", "pdf"}, CLI::ignore_case));
  add_submit_options(*cal, calibrate_command.submit);

  trapdem::app::ElementOptions element;
  auto* el = app.add_subcommand("element", "Virtual element test: friction angles of a configuration's particles (docs/element.md)");
  el->add_option("config", element.config_file, "Run configuration (TOML); default: the demo preset")->check(CLI::ExistingFile);
  el->add_option("--preset", element.preset, "Use a preset's particles and contact law");
  el->add_option("--test", element.test, "biaxial (plane strain, default) or triaxial")
      ->check(CLI::IsMember({"biaxial", "triaxial"}));
  el->add_option("--confining", element.confining, "Confining stress(es), Pa: 50e3 or 25e3,50e3,100e3 (default 50e3)")
      ->delimiter(',');
  el->add_option("--out", element.out_dir, "Output folder (default ./trapdem-out/element-<name>)");
  el->add_option("--set", element.overrides, "Override a key: --set element.particles=2000 (repeatable)");
  el->add_option("--threads", element.threads, "OpenMP threads (default: numerics.threads, else all cores)")
      ->check(thread_count);
  el->add_flag("--quiet", element.quiet, "No progress lines on the terminal (element.log keeps them)");

  trapdem::app::DepositOptions deposit;
  auto* dep = app.add_subcommand("deposit", "The fill's deposit: solid fraction, coordination, surface, before the trapdoor moves");
  dep->add_option("dir", deposit.dir, "Run folder (snapshots.h5, resolved.toml)")->required()->check(CLI::ExistingDirectory);

  if (const std::string refused = unknown_command_message(app, argc, argv); !refused.empty()) {
    fmt::print(stderr, "{}\n", refused);
    return trapdem::kExitInputError;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help exits 0; every command-line error is an input error, exit 2 as a bad
    // configuration is (README, Exit codes), not CLI11's own codes (105, 106, 109, ...).
    const int cli11_code = app.exit(e);
    return cli11_code == 0 ? 0 : trapdem::kExitInputError;
  }
  try {
    if (run_cmd->parsed()) return trapdem::app::run_experiment(run);
    if (presets_cmd->parsed()) return trapdem::app::list_presets();
    if (sc->parsed()) return trapdem::app::run_showcase(showcase);
    if (an->parsed()) return trapdem::app::run_analyze(analyze);
    if (fig->parsed()) return trapdem::app::run_figure(figure);
    if (piv_cmd->parsed()) return trapdem::app::run_piv_command(piv);
    if (synth_cmd->parsed()) return trapdem::app::run_synth_command(synth);
    if (render_cmd->parsed()) return trapdem::app::run_render_command(render);
    if (cmp_cmd->parsed()) return trapdem::app::run_compare(compare);
    if (sink->parsed()) return trapdem::app::run_sinkhole(sinkhole);
    if (study_cmd->parsed()) return trapdem::app::run_study(study);
    if (cal->parsed()) return trapdem::app::run_calibrate(calibrate_command);
    if (el->parsed()) return trapdem::app::run_element(element);
    if (dep->parsed()) return trapdem::app::run_deposit(deposit);
  } catch (const trapdem::InputError& e) {
    fmt::print(stderr, "trapdem: input error: {}\n", e.what());
    return trapdem::kExitInputError;
  } catch (const trapdem::SimulationError& e) {
    fmt::print(stderr, "trapdem: run stopped: {}\n", e.what());
    return trapdem::kExitRunStopped;
  } catch (const trapdem::FileError& e) {
    fmt::print(stderr, "trapdem: file error: {}\n", e.what());
    return trapdem::kExitFileError;
  } catch (const std::exception& e) {
    fmt::print(stderr, "trapdem: error: {}\n", e.what());
    return trapdem::kExitUnexpected;
  }
  return 0;
}
