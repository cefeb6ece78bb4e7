#pragma once
// Strain from PIV displacements through the analysis module: the valid subset centres are the
// nodes, triangulated (Delaunay, CGAL) and filtered in image 1, and each triangle is a constant
// strain triangle (cst_gradient.hpp) — the same code the DEM analysis uses, so PIV and DEM strains
// are directly comparable. Coordinates in model units (pixel_to_model.hpp), z up; strains
// compression positive (plane_strain.hpp).
#include <cstddef>
#include <vector>

#include "analysis/plane_strain.hpp"
#include "analysis/point_set.hpp"
#include "analysis/triangle_mesh.hpp"
#include "piv/piv_result.hpp"
#include "piv/pixel_to_model.hpp"

namespace trapdem {

struct PivStrainSettings {
  double max_edge_in_steps = 1.5;  // drop triangles with an edge longer than this many grid steps
  double min_angle_deg = 10.0;     // drop slivers
};

struct PivStrainField {
  std::vector<std::size_t> subset;   // grid index of each node
  std::vector<Point2> position;      // model units, node in image 1
  std::vector<Point2> displacement;  // model units, total from image 1 to the image asked for
  TriangleMesh mesh;                 // triangles kept (indices into position)
  std::vector<PlaneStrain> strain;   // per triangle, compression positive
  std::vector<double> max_shear;     // gamma_max per triangle
  std::vector<double> volumetric;    // e_vol per triangle, compression positive
};

// Total strain from image 1 to `image` (0-based) over the subsets valid in that image.
PivStrainField piv_total_strain(const PivResult& result, std::size_t image, const PixelToModel& to_model_units,
                                const PivStrainSettings& settings = {});

// Incremental strain from image - 1 to `image` over the subsets valid in both, each triangle's
// strain over its geometry in image - 1 (updated Lagrangian). `displacement` is the increment.
PivStrainField piv_incremental_strain(const PivResult& result, std::size_t image,
                                      const PixelToModel& to_model_units, const PivStrainSettings& settings = {});

// Increments accumulated from image 1 to `image` over the subsets valid in all of them (the
// same soil elements throughout; White & Bolton 2004). `strain` holds the summed components,
// `max_shear` the summed incremental gamma_max (cumulative shear).
PivStrainField piv_accumulated_strain(const PivResult& result, std::size_t image,
                                      const PixelToModel& to_model_units, const PivStrainSettings& settings = {});

}  // namespace trapdem
