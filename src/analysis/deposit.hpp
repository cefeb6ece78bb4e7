#pragma once
// The deposit a fill leaves: solid fraction and coordination number by height, the surface height,
// and their bulk values. What a faster fill must reproduce before it may replace the slow pour
// (docs/validation.md): the same density, its profile with height and the same contact network.
// And the geostatic vertical stress with height, the weight of the deposit above a level per unit
// of the box's plan area, under the body acceleration the deposit was in (uniform N g, or a
// centrifuge's, which grows with depth: Taylor 1995, section 2.4).
#include <functional>
#include <limits>
#include <vector>

#include "io/snapshot.hpp"

namespace trapdem {

struct DepositSettings {
  double box_width = 0.0;       // m (x from 0)
  double box_depth = 0.0;       // m (y from 0)
  bool periodic_depth = false;  // y periodic: contacts across y = 0 / depth count
  double bin_height = 0.0;      // m; 0: five mean diameters
  // The bulk layer, where the base and the free surface do not matter: from `base_margin` above
  // the base to `surface_margin` below the surface, in mean diameters.
  double base_margin = 5.0;
  double surface_margin = 5.0;
  // The geostatic stress: the solid's density (kg/m^3) and the body acceleration's downward (-z)
  // component at a position (m/s^2). Without both, no stress is given (NaN).
  double solid_density = 0.0;
  std::function<double(const Vec3&)> downward_acceleration;
};

struct DepositBin {
  double z_low = 0.0, z_high = 0.0;  // m
  double solid_fraction = 0.0;       // sphere volume inside the slab / slab volume
  double coordination = 0.0;         // contacts per particle whose centre is in the slab
  int particles = 0;                 // centres in the slab
  // Pa, the geostatic vertical stress at the slab's lower face z_low: sum over the particles of
  // rho (the part of the sphere's volume above z_low) a_down(centre), over the plan area.
  double geostatic_stress = std::numeric_limits<double>::quiet_NaN();
};

struct DepositMetrics {
  int particles = 0;
  double mean_diameter = 0.0;       // m
  double surface_height = 0.0;      // m, mean over columns two mean diameters wide of the highest top
  double surface_roughness = 0.0;   // m, standard deviation of those column tops
  double bulk_z_low = 0.0, bulk_z_high = 0.0;  // m, the bulk layer
  double bulk_solid_fraction = 0.0;
  double bulk_coordination = 0.0;   // contacts (overlap > 0, walls not counted) per particle
  double bulk_rattler_fraction = 0.0;  // particles with fewer than two contacts
  // Overlap of the particle contacts, relative to the pair's mean diameter r_i + r_j, over the whole
  // deposit: what a softer spring must keep small (the paper's k_n discussion; docs/validation.md).
  double mean_overlap = 0.0;
  double max_overlap = 0.0;
  long contacts = 0;
  std::vector<DepositBin> profile;  // from the base up to the highest top
  double base_geostatic_stress = std::numeric_limits<double>::quiet_NaN();  // Pa, at z = 0: the whole weight
};

// Throws InputError for an empty snapshot, a box of no size or particles outside it in x or y.
// A snapshot of clumps is measured by its grains: `particles`, the mean (volume-equivalent)
// diameter, the coordination and rattlers per clump (by its centre of mass), counting the contacts
// between members of different clumps only (a clump's own members overlap by design); the solid
// fraction and the weights from the members' spheres, each scaled by its clump's union volume over
// its members' summed volume (the overlaps would count twice); the surface of the members' tops.
DepositMetrics measure_deposit(const Snapshot& snapshot, const DepositSettings& settings);

// The volume (m^3) of a sphere of radius r centred at height zc that lies below the plane z = a:
// a cap of height h = a - (zc - r) has pi h^2 (3 r - h) / 3.
double sphere_volume_below(double zc, double r, double a);

}  // namespace trapdem
