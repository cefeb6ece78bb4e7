#pragma once
// The DEM camera: a snapshot drawn as a camera sees the model through its front window (the
// glass at y = front_wall_y), so that `trapdem piv` can be run on DEM "photographs" and compared
// with the particles — the bridge between centrifuge PIV and DEM. Orthographic view along -y:
// image x = model x, image rows downward = model z upward, a fixed scale. Only particles whose
// centre lies within `layer_depth` (default one largest diameter) of the front wall are drawn,
// farthest first, as shaded discs like glass beads: a radial gradient, a small highlight, and a
// random grey level per particle id (from the seed) so the texture is speckle-like; dark background.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

#include "io/snapshot.hpp"
#include "piv/piv_result.hpp"
#include "piv/pixel_to_model.hpp"

namespace trapdem {

struct CameraView {
  double mm_per_px = 0.25;
  double origin_x_mm = 0.0;  // model x of pixel (0, 0)'s centre, mm
  double origin_z_mm = 0.0;  // model z of pixel (0, 0)'s centre, mm (z up; image y down)
  int width = 0;             // px
  int height = 0;            // px

  cv::Point2d to_pixel(double x_mm, double z_mm) const {
    return {(x_mm - origin_x_mm) / mm_per_px, (origin_z_mm - z_mm) / mm_per_px};
  }
  // Pixels to model mm (x right, z up): what `trapdem piv --scale mm_per_px --origin X,Z` uses.
  PixelToModel to_model_mm() const {
    return scale_transform(mm_per_px, {-origin_x_mm / mm_per_px, origin_z_mm / mm_per_px});
  }
};

struct CameraSettings {
  double front_wall_y = 0.0;  // m, the glass (box.depth)
  double layer_depth = 0.0;   // m, particle centres within this of the wall are drawn; 0: largest diameter
  double background = 12.0;   // grey levels
  std::uint64_t seed = 7;     // grey level of each particle from (seed, id)
};

// A view of x in [0, box_width] and z over every snapshot's front-layer particles (with a 2 mm
// margin, and z down to 0 at least), at px_per_mm. Throws InputError if px_per_mm <= 0 or there
// are no particles.
CameraView camera_view_for(const std::vector<Snapshot>& snapshots, double box_width_m, double px_per_mm,
                           const CameraSettings& settings);

// Whether particle i is in the front layer (settings.layer_depth resolved against `snapshot`).
std::vector<bool> front_layer(const Snapshot& snapshot, const CameraSettings& settings);

// The snapshot as an 8-bit grey image of view.width x view.height.
cv::Mat render_front_view(const Snapshot& snapshot, const CameraView& view, const CameraSettings& settings);

// The snapshot at which lowering starts, by its index in a run's snapshots (given their trapdoor
// displacements, m): the last one before the trapdoor first moved (more than 1 um), the analysis'
// 0 mm reference. PIV from there measures the lowering only: the images before it (pour, settling,
// spin-up) would add their settlement to the strain. 0 when the trapdoor never moved.
std::size_t lowering_start(const std::vector<double>& trapdoor_displacements);

// PIV displacement of image `image` against the particles: for each valid subset, the mean
// displacement (first -> current snapshot, matched by id) of the front-layer particles of the
// first snapshot whose image-1 centre lies inside the subset square.
struct CameraAgreement {
  std::size_t subsets = 0;             // valid subsets with at least one particle
  double rms_error_px = 0.0;           // |PIV - particles| (vector), RMS over subsets
  double rms_vertical_error_px = 0.0;  // v only
  double rms_vertical_error_mm = 0.0;
  double max_particle_displacement_px = 0.0;  // largest subset-mean particle displacement
  double mean_vertical_error_px = 0.0;        // bias of v (PIV - particles)
};

CameraAgreement compare_with_particles(const PivResult& result, std::size_t image, const Snapshot& first,
                                       const Snapshot& current, const CameraView& view,
                                       const CameraSettings& settings);

}  // namespace trapdem
