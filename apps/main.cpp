// trapdem: the command line. Each subcommand is one stage of the work, from packing to figures.
#include <exception>

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include "dem/errors.hpp"
#include "showcase.hpp"

int main(int argc, char** argv) {
  CLI::App app{"trapdem: trapdoor experiments with the discrete element method"};
  app.require_subcommand(1);

  trapdem::app::ShowcaseOptions showcase;
  auto* sc = app.add_subcommand("showcase", "A packing settles in a box under gravity; prints speed and floor load");
  sc->add_option("--particles", showcase.particles, "Number of spheres")->check(CLI::PositiveNumber);
  sc->add_option("--threads", showcase.threads, "OpenMP threads (default: all cores)")->check(CLI::NonNegativeNumber);

  CLI11_PARSE(app, argc, argv);
  try {
    if (sc->parsed()) return trapdem::app::run_showcase(showcase);
  } catch (const trapdem::InputError& e) {
    fmt::print(stderr, "trapdem: input error: {}\n", e.what());
    return 2;
  } catch (const trapdem::SimulationError& e) {
    fmt::print(stderr, "trapdem: run stopped: {}\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    fmt::print(stderr, "trapdem: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
