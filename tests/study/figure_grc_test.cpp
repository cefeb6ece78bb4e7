// `trapdem figure --grc DIR...` (apps/analyze_command.hpp, src/study/ground_reaction_overlay.hpp):
// three run folders with their own trapdoor.csv give a chart with one curve per run, each in its
// series colour (read back from the PNG), the legend from the runs' names (the folder added where
// two share a name) or --labels; a folder without trapdoor.csv is an input error naming the file.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "analyze_command.hpp"
#include "core/errors.hpp"
#include "experiment/ground_reaction.hpp"
#include "io/atomic_file.hpp"
#include "plot/colour_map.hpp"
#include "study/ground_reaction_overlay.hpp"
#include "../plot/png_image.hpp"
#include "../io/io_test_support.hpp"

namespace trapdem {
namespace {

namespace fs = std::filesystem;

// A run folder with resolved.toml (trapdoor B = 20 mm) and a ground reaction curve falling to `floor`.
fs::path make_run(const fs::path& dir, const std::string& name, double floor) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "resolved.toml") << "name = \"" << name
                                       << "\"\n[box]\nwidth = 0.2\ndepth = 0.01\nheight = 0.14\n"
                                          "[trapdoor]\nwidth = 0.02\ncentre = 0.1\ntravel = 0.01\ncavity_depth = 0.02\n"
                                          "[particles]\nsize = \"single\"\ndiameter = 0.002\n";
  std::vector<GroundReactionRow> rows;
  for (int k = 0; k <= 40; ++k) {
    GroundReactionRow r;
    r.trapdoor_displacement = 0.0001 * k;
    r.trapdoor.ratio = floor + (1.0 - floor) * std::exp(-0.5 * k);
    r.geostatic_stress = 1e4;
    rows.push_back(r);
  }
  write_text_atomically(dir / "trapdoor.csv", ground_reaction_csv(rows));
  return dir;
}

// Pixels within 6 levels of a series colour (line cores; the legend's sample lines count too).
int pixels_of(const test::PngImage& image, plot::Rgb c) {
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      n += std::abs(image.red(x, y) - static_cast<int>(std::lround(255 * c.r))) <= 6 &&
           std::abs(image.green(x, y) - static_cast<int>(std::lround(255 * c.g))) <= 6 &&
           std::abs(image.blue(x, y) - static_cast<int>(std::lround(255 * c.b))) <= 6;
    }
  }
  return n;
}

TEST(FigureGrc, OneCurvePerRun) {
  const io_testing::ScratchDir root("trapdem-figure-grc");
  const std::vector<std::string> dirs{make_run(root / "loose", "rf1", 0.2).string(),
                                      make_run(root / "dense", "rf1", 0.4).string(),
                                      make_run(root / "other", "rf2", 0.6).string()};
  app::FigureOptions o;
  o.dirs = dirs;
  o.grc = true;
  o.out = (root / "grc.png").string();
  ASSERT_EQ(app::run_figure(o), 0);
  const test::PngImage image = test::read_png(root / "grc.png");
  ASSERT_GT(image.width, 0);
  for (std::size_t k = 0; k < 3; ++k) {
    const int n = pixels_of(image, plot::series_colour(k));
    std::printf("[ measured ] curve %zu: %d pixels of its colour\n", k, n);
    EXPECT_GT(n, 400) << "run " << k << " has its curve";
  }
  EXPECT_EQ(pixels_of(image, plot::series_colour(3)), 0) << "no fourth curve";
  // Legend: the names, the folder where two runs share one.
  std::vector<fs::path> paths(dirs.begin(), dirs.end());
  EXPECT_EQ(ground_reaction_legend(paths, {"rf1", "rf1", "rf2"}, {}),
            (std::vector<std::string>{"rf1 (loose)", "rf1 (dense)", "rf2"}));
  EXPECT_EQ(ground_reaction_legend(paths, {"rf1", "rf1", "rf2"}, {"A", "B", "C"}),
            (std::vector<std::string>{"A", "B", "C"}));
  // As SVG, with the labels given; the extension picks the format.
  o.out = (root / "grc.svg").string();
  o.panel.labels = {"loose", "dense", "other"};
  ASSERT_EQ(app::run_figure(o), 0);
  std::ifstream svg(root / "grc.svg");
  std::string head(5, ' ');
  svg.read(head.data(), 5);
  EXPECT_EQ(head, "<?xml");
}

TEST(FigureGrc, BadInputNamesTheProblem) {
  const io_testing::ScratchDir root("trapdem-figure-grc-bad");
  make_run(root / "a", "a", 0.3);
  make_run(root / "b", "b", 0.3);
  fs::remove(root / "b" / "trapdoor.csv");
  app::FigureOptions o;
  o.grc = true;
  o.dirs = {(root / "a").string(), (root / "b").string()};
  o.out = (root / "grc.png").string();
  try {
    app::run_figure(o);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("trapdoor.csv"), std::string::npos) << e.what();
  }
  o.dirs = {(root / "a").string()};
  o.out = (root / "grc.gif").string();
  EXPECT_THROW(app::run_figure(o), InputError);
  o.out = (root / "grc.png").string();
  o.panel.labels = {"one", "two"};
  EXPECT_THROW(app::run_figure(o), InputError);
}

}  // namespace
}  // namespace trapdem
