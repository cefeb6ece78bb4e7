// The binary seeds of `make fuzz`, written into the fuzz build folder rather than kept in git:
// snapshots.h5 (two snapshots), checkpoint.h5 (a small settled box) and one small image per format
// OpenCV reads (PNG 8 and 16 bit, TIFF, BMP, JPEG). Usage: make_seeds SNAPSHOT_DIR IMAGE_DIR
#include <cstdio>
#include <filesystem>

#include <opencv2/imgcodecs.hpp>

#include "io/checkpoint.hpp"
#include "io/snapshot.hpp"

using namespace trapdem;
namespace fs = std::filesystem;

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s SNAPSHOT_DIR IMAGE_DIR\n", argv[0]);
    return 2;
  }
  const fs::path snapshots = argv[1], images = argv[2];
  fs::create_directories(snapshots);
  fs::create_directories(images);

  ContactLaw law;
  Particles p;
  for (int i = 0; i < 4; ++i) p.add(i + 1, {0.002 * i, 0.001, 0.001 + 0.0005 * i}, 0.001, 2500.0);
  SimulationSettings settings;
  settings.domain.lower = {-0.01, -0.01, -0.01};
  settings.domain.upper = {0.02, 0.01, 0.02};
  Simulation simulation(p, law, settings);
  simulation.add_wall(Wall::plane("floor", {0, 0, 0}, {0, 0, 1}, law));
  simulation.run(10);
  save_checkpoint(snapshots / "checkpoint.h5", simulation, {{"stage", "lowering"}});

  const fs::path one_file = snapshots / "snapshots.h5";
  fs::remove(one_file);
  append_snapshot(one_file, make_snapshot(simulation.particles(), 0.0, "pour", 0.0, 0));
  append_snapshot(one_file, make_snapshot(simulation.particles(), 0.1, "lowering", 0.001, 10));

  cv::Mat grey(6, 5, CV_8UC1), colour(4, 3, CV_8UC3), deep(3, 3, CV_16UC1);
  cv::randu(grey, 0, 255);
  cv::randu(colour, 0, 255);
  cv::randu(deep, 0, 65535);
  cv::imwrite((images / "grey.png").string(), grey);
  cv::imwrite((images / "deep.png").string(), deep);
  cv::imwrite((images / "deep.tif").string(), deep);
  cv::imwrite((images / "colour.bmp").string(), colour);
  cv::imwrite((images / "colour.jpg").string(), colour);
  return 0;
}
