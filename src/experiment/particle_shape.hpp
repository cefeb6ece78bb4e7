#pragma once
// [particles.shape]: the grains' shape (issue 39). Spheres by default; otherwise every grain is a
// rigid clump of overlapping spheres (dem/rigid/) of one shape, a built-in family or a template
// file, scaled to each grain's volume-equivalent diameter from the size distribution
// ([particles] diameter, grading: the diameter of the sphere of the grain's volume).
#include <memory>
#include <string>

#include "dem/rigid/clump_template.hpp"

namespace trapdem {

class Config;

struct ParticleShape {
  std::string kind = "sphere";  // sphere, dimer, tetrahedral, sub_angular, file
  // The clump's shape at a volume-equivalent diameter of 1 m; null for spheres.
  std::shared_ptr<const ClumpTemplate> clump;

  bool is_clump() const { return clump != nullptr; }
  // The radius of the sphere about the centre of mass that holds the grain, over the
  // volume-equivalent radius (1 for a sphere): the room a grain needs in the hopper band.
  double bounding_ratio() const;
  std::string describe() const;  // for run.log: the kind, its parameters and the member count
};

// Reads the [particles.shape] table (absent: spheres). A key of another kind is refused naming the
// kind that reads it; a bad template (no sphere, a member apart from the others, a file that does
// not parse) is refused naming the file and line.
ParticleShape read_particle_shape(Config& shape);

}  // namespace trapdem
