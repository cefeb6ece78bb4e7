#pragma once
// A run's snapshots drawn as the camera sees them through the front window, into a folder, with the
// PIV that measures them suggested (scale.txt), and the check of that PIV against the particles:
// what `trapdem render` does (docs/piv.md), as library calls for any front end.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "piv/dem_camera.hpp"

namespace trapdem {

struct CameraRenderOptions {
  std::filesystem::path run;     // the run folder (snapshots.h5, resolved.toml)
  std::filesystem::path out;     // empty: the run's camera/ folder
  double px_per_mm = 4.0;
  std::filesystem::path config;  // the geometry; empty: the run's resolved.toml
};

struct CameraRender {
  std::filesystem::path out;
  std::vector<std::filesystem::path> images;  // one per snapshot, in order
  std::vector<Snapshot> snapshots;
  double px_per_mm = 0.0;  // as asked for
  CameraView view;
  CameraSettings camera;
  std::size_t lowering_starts_at = 0;  // the first image of the lowering (the PIV's reference)
  std::string piv_command;             // the suggested `trapdem piv ...` line (also in scale.txt)
};

// Writes NNN_<displacement>mm.png per snapshot and scale.txt. Throws InputError for a run without
// snapshots, FileError when the folder cannot be written.
CameraRender render_run_snapshots(const CameraRenderOptions& options);

// The check: PIV (subsets of `subset` px, 0: about three particle diameters; `threads`) on the images
// from the start of the lowering, against the front-layer particles' mean displacement per subset.
struct CameraCheckRow {
  double trapdoor_displacement = 0.0;  // m
  CameraAgreement agreement;
};
struct CameraCheck {
  int subset = 0, step = 0;  // px
  std::vector<CameraCheckRow> rows;  // empty: no snapshot after the trapdoor started to move
};
CameraCheck check_rendered_piv(const CameraRender& render, int subset, int threads);

}  // namespace trapdem
