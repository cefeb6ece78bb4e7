// trapdem: the command line. Each subcommand is one stage of the work, from packing to figures.
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "dem/errors.hpp"
#include "io/file_error.hpp"
#include "run_command.hpp"
#include "showcase.hpp"

int main(int argc, char** argv) {
  CLI::App app{"trapdem: trapdoor experiments with the discrete element method"};
  app.require_subcommand(1);

  trapdem::app::RunOptions run;
  auto* run_cmd = app.add_subcommand("run", "Run a trapdoor experiment: pluviation, settling, spin-up, lowering");
  run_cmd->add_option("config", run.config_file, "Configuration file (TOML); default: the demo preset")
      ->check(CLI::ExistingFile);
  run_cmd->add_option("--preset", run.preset, "Run a preset (see `trapdem presets`)");
  run_cmd->add_option("--out", run.out_dir, "Output folder (default: ./trapdem-out/<name>)");
  run_cmd->add_option("--threads", run.threads, "OpenMP threads (default: numerics.threads, else all cores)")
      ->check(CLI::NonNegativeNumber);
  run_cmd->add_option("--set", run.overrides, "Override a key: --set trapdoor.rate=0.1 (repeatable)");
  run_cmd->add_option("--resume", run.resume_dir, "Carry on the run in this folder from its checkpoint")
      ->check(CLI::ExistingDirectory);
  run_cmd->add_flag("--quiet", run.quiet, "No progress lines on the terminal (run.log keeps them)");
  run_cmd->add_option("--stop-after", run.stop_after_seconds,
                      "Stop with a checkpoint after this many seconds of wall clock");

  auto* presets_cmd = app.add_subcommand("presets", "List the presets, one line each");

  trapdem::app::ShowcaseOptions showcase;
  auto* sc = app.add_subcommand("showcase", "A packing settles in a box under gravity; prints speed and floor load");
  sc->add_option("--particles", showcase.particles, "Number of spheres")->check(CLI::PositiveNumber);
  sc->add_option("--threads", showcase.threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);

  CLI11_PARSE(app, argc, argv);
  try {
    if (run_cmd->parsed()) return trapdem::app::run_experiment(run);
    if (presets_cmd->parsed()) return trapdem::app::list_presets();
    if (sc->parsed()) return trapdem::app::run_showcase(showcase);
  } catch (const trapdem::InputError& e) {
    fmt::print(stderr, "trapdem: input error: {}\n", e.what());
    return 2;
  } catch (const trapdem::SimulationError& e) {
    fmt::print(stderr, "trapdem: run stopped: {}\n", e.what());
    return 3;
  } catch (const trapdem::FileError& e) {
    fmt::print(stderr, "trapdem: file error: {}\n", e.what());
    return 4;
  } catch (const std::exception& e) {
    fmt::print(stderr, "trapdem: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
