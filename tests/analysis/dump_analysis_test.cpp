// LAMMPS/LIGGGHTS text dumps (io/lammps_dump.hpp) as the input of the analysis.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "analysis/analysis_run.hpp"
#include "core/errors.hpp"
#include "../scratch_dir.hpp"

using namespace trapdem;

// Dumps through the whole analysis: the same particles in two files, the second moved down
// uniformly with the trapdoor's 1 mm: no strain, the matched count is every particle.
TEST(DumpReader, FeedsTheAnalysis) {
  namespace fs = std::filesystem;
  const test::ScratchDir dir("trapdem-dump-analysis");
  std::vector<fs::path> files;
  for (int f = 0; f < 2; ++f) {
    files.push_back(dir / ("dump." + std::to_string(f)));
    std::ofstream out(files.back());
    int n = 0;
    std::string atoms;
    for (int i = 0; i < 40; ++i) {
      for (int j = 0; j < 20; ++j) {
        const double x = 0.0025 + 0.005 * i + 0.0025 * (j % 2), z = 0.0025 + 0.0043 * j - 0.001 * f;
        atoms += std::to_string(++n) + " " + std::to_string(x) + " 0.0075 " + std::to_string(z) + " 0.0025\n";
      }
    }
    out << "ITEM: TIMESTEP\n" << f << "\nITEM: NUMBER OF ATOMS\n" << n
        << "\nITEM: BOX BOUNDS ff ff ff\n0 0.2\n0 0.01\n0 0.1\nITEM: ATOMS id x y z radius\n" << atoms;
  }
  SpecimenGeometry g{"dumps", 0.2, 0.01, 0.14, {0.1, 0.05, 0.0}};
  const AnalysisResult r = analyze_dump_files(files, {0.0, 0.001}, g, AnalysisSettings{});
  EXPECT_EQ(r.matched_particles, 800u);
  EXPECT_EQ(r.id.size(), 800u);
  for (double gamma : r.gamma_max) EXPECT_LT(gamma, 1e-9);
  EXPECT_THROW(analyze_dump_files(files, {0.0}, g, AnalysisSettings{}), InputError);
}
