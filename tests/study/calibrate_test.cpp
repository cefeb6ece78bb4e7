// trapdem calibrate end to end on the DEM camera: a tiny run with planted parameters is rendered as
// the camera sees it, PIV measures its settlement, and the calibration grid must rank the planted
// parameters first.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include <fmt/format.h>

#include "study/calibration.hpp"
#include "core/errors.hpp"
#include "experiment/experiment_config.hpp"
#include "io/config.hpp"
#include "io/text_file.hpp"
#include "piv_command.hpp"
#include "run_command.hpp"
#include "../scratch_dir.hpp"

namespace fs = std::filesystem;
using namespace trapdem;
using trapdem::test::ScratchDir;

namespace {

// The tiny preset shortened (a shallow pour, 3 mm of travel, a snapshot every millimetre).
fs::path write_base(const fs::path& dir) {
  Config c = Config::load_file((app::preset_directory() / "tiny.toml").string());
  c.apply_overrides({"pluviation.fill_height=0.02", "settling.max_time=0.04", "trapdoor.travel=0.003",
                     "output.snapshot_displacements=[0.0, 0.001, 0.002, 0.003]"});
  ExperimentConfig::from(c);
  const fs::path file = dir / "base.toml";
  std::ofstream(file) << c.resolved_toml();
  return file;
}

double scale_value(const std::string& scale_txt, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(scale_txt, m, std::regex(key + " = ([-0-9.e]+)"))) throw std::runtime_error("no " + key);
  return std::stod(m[1]);
}

}  // namespace

TEST(Calibrate, VaryParsesKeysAndValuesAndRefusesMistakes) {
  const VariedKey v = parse_vary("contact.rolling_friction = 0.1, 0.2 ,0.4");
  EXPECT_EQ(v.key, "contact.rolling_friction");
  EXPECT_EQ(v.values, (std::vector<std::string>{"0.1", "0.2", "0.4"}));
  EXPECT_THROW(parse_vary("contact.rolling_friction"), InputError);
  EXPECT_THROW(parse_vary("=0.1"), InputError);
  EXPECT_THROW(parse_vary("a.b=0.1,,0.2"), InputError);
  EXPECT_THROW(parse_vary("a.b=0.1,0.1"), InputError);
}

TEST(Calibrate, PivOfARenderedTinyRunRanksItsOwnParametersFirst) {
  const ScratchDir scratch("trapdem-calibrate-planted");
  const fs::path& dir = scratch.path();
  const fs::path base = write_base(dir);

  // The "experiment": mu_k = 0.5, mu_r = 0.3 (the tiny preset has mu_s = 0.5, so mu_k <= mu_s and
  // every value of mu_k acts; with mu_k > mu_s a grid would hold physically identical cases).
  app::RunOptions planted;
  planted.config_file = base.string();
  planted.overrides = {"contact.kinetic_friction=0.5", "contact.rolling_friction=0.3"};
  planted.out_dir = (dir / "planted").string();
  planted.threads = 1;
  planted.quiet = true;
  ASSERT_EQ(app::run_experiment(planted), 0);
  app::RenderOptions render;
  render.dir = planted.out_dir;
  ASSERT_EQ(app::run_render_command(render), 0);
  const fs::path camera = dir / "planted" / "camera";
  const std::string scale_txt = read_text_file(camera / "scale.txt");
  // PIV from the start of lowering (image 002_0mm.png: the snapshots before it are the pour and the
  // settling, whose motion a centrifuge camera would not see either).
  app::PivOptions piv;
  for (const char* image : {"002_0mm.png", "003_1mm.png", "004_2mm.png", "005_3mm.png"})
    piv.images.push_back((camera / image).string());
  piv.out = (dir / "piv").string();
  piv.scale = scale_value(scale_txt, "mm_per_px");
  piv.origin = fmt::format("{},{}", scale_value(scale_txt, "origin_x_mm"), scale_value(scale_txt, "origin_z_mm"));
  piv.no_figures = true;
  piv.quiet = true;
  ASSERT_EQ(app::run_piv_command(piv), 0);

  CalibrateOptions o;
  o.base = base.string();
  o.vary = {"contact.kinetic_friction=0.2,0.5", "contact.rolling_friction=0.05,0.3"};
  o.target = piv.out;
  o.at = "3mm";
  o.out = (dir / "calibration").string();
  o.threads = 1;  // the planted run's thread count: its case reproduces it bit for bit
  o.quiet = true;
  const Calibration c = calibrate(o);
  ASSERT_TRUE(c.complete);
  ASSERT_EQ(c.ranked.size(), 4u);
  EXPECT_EQ(c.ranked[0].values, (std::vector<std::string>{"0.5", "0.3"}));
  // What is left for the planted case is the PIV's own error (~10 % of delta on this coarse image,
  // four particle layers); every other case adds its mechanism's difference, measured 17-28 %.
  EXPECT_LT(c.ranked[0].error, 0.15);
  EXPECT_GT(c.ranked[1].error, 1.3 * c.ranked[0].error);
  for (const char* f : {"calibration.csv", "best.toml", "error_surface.png", "compare_best.png", "report/index.html"})
    EXPECT_TRUE(fs::exists(c.out / f)) << f;
  const std::string csv = read_text_file(c.out / "calibration.csv");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "rank,case,contact.kinetic_friction,contact.rolling_friction,rms_over_delta,bias_over_delta,coverage");
  EXPECT_NE(csv.find("\n1,kinetic_friction-0.5_rolling_friction-0.3,0.5,0.3,"), std::string::npos) << csv;
  // best.toml is a configuration `trapdem run` takes as it is.
  Config best = Config::load_file((c.out / "best.toml").string());
  const ExperimentConfig e = ExperimentConfig::from(best);
  EXPECT_DOUBLE_EQ(e.material.particle.kinetic_friction, 0.5);
  EXPECT_DOUBLE_EQ(e.material.particle.rolling_friction, 0.3);

  EXPECT_EQ(read_text_file(c.out / "error_surface.png").substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));

  // Started again, nothing runs: every case is finished and the ranking is the same; asked for PDF
  // figures, the error surface, the comparison and the report's figures are PDF files.
  o.format = "pdf";
  const Calibration again = calibrate(o);
  EXPECT_EQ(again.ranked[0].case_name, c.ranked[0].case_name);
  EXPECT_DOUBLE_EQ(again.ranked[0].error, c.ranked[0].error);
  for (const char* f : {"error_surface.pdf", "compare_best.pdf", "report/strain_panel.pdf", "report/ground_reaction.pdf"}) {
    ASSERT_TRUE(fs::exists(c.out / f)) << f;
    EXPECT_EQ(read_text_file(c.out / f).substr(0, 5), "%PDF-") << f;
  }
  o.format = "eps";
  EXPECT_THROW(calibrate(o), InputError);
}
