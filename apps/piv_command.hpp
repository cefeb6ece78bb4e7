#pragma once
// `trapdem piv IMAGES... --out DIR`: PIV over a photograph sequence (src/piv), writing
// displacements.csv, piv.h5 and the figures. `trapdem synth`: synthetic speckle sequences under a
// prescribed displacement field, with truth.csv. `trapdem render DIR`: the DEM snapshots as the
// camera sees them through the front window (src/piv/dem_camera.hpp). docs/piv.md.
#include <optional>
#include <string>
#include <vector>

namespace trapdem::app {

struct PivOptions {
  std::vector<std::string> images;
  std::string out;
  int subset = 32;
  int step = 16;
  std::string roi;               // "x0,y0,x1,y1" px; empty: whole image
  std::optional<double> scale;   // mm per px
  std::string origin;            // "X,Z": model coordinates (mm) of pixel (0,0) with --scale; default 0,0
  std::string control_points;    // CSV x_px,y_px,x_model,z_model
  std::string fit = "projective";  // affine | projective, for --control-points
  int threads = 0;
  bool no_figures = false;
  std::string format = "png";    // figures: png | svg | pdf
  std::string contour_levels;    // settlement contour levels "0.5,1,2" in the plot unit; empty: automatic
  std::string contour_step;      // or a step "1"
  bool quiet = false;
};

int run_piv_command(const PivOptions& options);

struct SynthOptions {
  std::string field = "rigid";   // rigid | strain | shear | trapdoor
  std::string out;
  std::string size = "512x512";
  int images = 2;                // including the undeformed image 1
  double noise = 2.0;            // grey levels
  std::optional<double> magnitude;  // of the last image: px (rigid, trapdoor) or strain (strain, shear)
  unsigned seed = 1;
};

int run_synth_command(const SynthOptions& options);

struct RenderOptions {
  std::string dir;
  std::string out;               // default DIR/camera
  double px_per_mm = 4.0;
  std::string config;            // default DIR/resolved.toml
  bool check = false;            // run PIV on the images and compare with the particles
  int subset = 0;                // for --check; 0: about three particle diameters
  int threads = 0;
};

int run_render_command(const RenderOptions& options);

}  // namespace trapdem::app
