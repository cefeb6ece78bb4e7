#include "experiment/element_test.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "core/errors.hpp"
#include "experiment/element_servo.hpp"

namespace trapdem {


namespace {

constexpr double kDegree = 180.0 / std::numbers::pi;
// Isotropic equilibrium: each axis' stress, averaged over a window, within this fraction of the
// target (half the 1 % the servo is held to during shear) ...
constexpr double kStressTolerance = 0.005;
// ... and the particles' r.m.s. velocity below this fraction of the shear's own velocity scale,
// the axial strain rate times the mean diameter (the specimen is at rest compared to the shear).
constexpr double kRestFraction = 1.0;
constexpr int kWindowSteps = 500;        // steps of an equilibrium check window
constexpr int kStressSampleEvery = 10;   // steps between Love-Weber and coordination samples
// Steps between samples of the interior's stress: it copies the pair list (Simulation::pairs), a
// few times a step's own cost; every 50 steps is still ~40 samples in a row at I = 2e-3.
constexpr int kInteriorSampleEvery = 50;
constexpr double kRampStrain = 0.001;    // axial strain over which the shear's wall speed is reached

SimulationSettings simulation_settings(const ElementSetup& setup, double side) {
  SimulationSettings s;
  s.time_step = setup.time_step;
  s.skin = setup.skin;
  s.max_overlap_fraction = setup.max_overlap_fraction;
  // Room for the lateral walls to move out while the specimen dilates (the compressed specimen
  // is ~0.8 side wide; 30 % of axial strain widens it by less than half).
  s.domain.lower = Vec3{-0.5 * side, -0.5 * side, -0.5 * side};
  s.domain.upper = Vec3{1.5 * side, 1.5 * side, 1.5 * side};
  return s;
}

// The law the gas is compressed with: no friction and no rolling resistance for the dense
// specimen, the particles' own for the loose one, the preparation friction and no rolling
// resistance for one in between.
ContactLaw preparation_law(const ContactLaw& law, const Packing& packing) {
  switch (packing.kind) {
    case PackingKind::loose: return law;
    case PackingKind::dense: return frictionless(law);
    case PackingKind::preparation_friction: break;
  }
  ContactLaw prepared = frictionless(law);
  prepared.static_friction = packing.friction;
  prepared.kinetic_friction = packing.friction;
  return prepared;
}

double rms_velocity(const Simulation& sim) {
  return std::sqrt(2.0 * sim.translational_kinetic_energy() / sim.total_mass());
}

// Contacts per grain: per sphere, or per clump (a clump's members' contacts with other clumps).
double coordination_number(const Simulation& sim) {
  const std::size_t grains = sim.bodies().empty() ? sim.particles().size() : sim.bodies().size();
  return grains == 0 ? 0.0 : 2.0 * double(sim.contact_count()) / double(grains);
}

Vec3 diagonal(const Stress3& s) { return {s[0][0], s[1][1], s[2][2]}; }

// Runs the servos of all three axes at `target` until the window-averaged stresses are within
// kStressTolerance and the particles at rest, then one more window to measure the state.
void equilibrate(ElementSpecimen& sp, const ElementSetup& setup, double max_speed, std::int64_t max_steps,
                 const ElementLog& log) {
  Simulation& sim = *sp.sim;
  StressServo servo[3];
  const double response = wall_contact_response(sim, sp.box);
  for (auto& s : servo) s = StressServo(sp.confining, max_speed, response);
  const double rest_velocity =
      kRestFraction * shear_strain_rate(setup, sp.confining) * setup.material.sizes.mean_diameter();
  std::int64_t steps = 0;
  for (;;) {
    Vec3 sum;
    for (int k = 0; k < kWindowSteps; ++k) {
      sim.step();
      const std::vector<int> contacts = wall_contact_counts(sim);
      for (int a = 0; a < 3; ++a) servo[a].update(sim, sp.box, a, contacts);
      sum += wall_stress(sim, sp.box);
    }
    steps += kWindowSteps;
    const Vec3 mean = sum / kWindowSteps;
    double error = 0.0;
    for (int a = 0; a < 3; ++a) error = std::max(error, std::fabs(mean[a] - sp.confining) / sp.confining);
    const double v = rms_velocity(sim);
    if (error < kStressTolerance && v < rest_velocity) break;
    if (steps >= max_steps)
      throw SimulationError(fmt::format(
          "element test: the {} specimen did not reach isotropic equilibrium at {:.4g} Pa within {} steps (stress "
          "off by {:.2g} %, r.m.s. velocity {:.3g} m/s, at rest below {:.3g} m/s): lower element.inertial_number "
          "or check the contact law",
          to_string(sp.packing), sp.confining, steps, 100.0 * error, v, rest_velocity));
    if (log && steps % (20 * kWindowSteps) == 0)
      log(fmt::format("  {} {:.0f} Pa: step {}, stresses {:.4g} {:.4g} {:.4g} Pa, r.m.s. velocity {:.3g} m/s",
                      to_string(sp.packing), sp.confining, steps, mean.x, mean.y, mean.z, v));
  }
  // The measuring window: the servos keep running.
  Vec3 wall_sum, lw_sum;
  double z_sum = 0.0;
  int samples = 0;
  for (int k = 0; k < kWindowSteps; ++k) {
    sim.step();
    const std::vector<int> contacts = wall_contact_counts(sim);
    for (int a = 0; a < 3; ++a) servo[a].update(sim, sp.box, a, contacts);
    if (k % kStressSampleEvery == 0) {
      wall_sum += wall_stress(sim, sp.box);
      lw_sum += diagonal(love_weber_stress(sim, sp.box));
      z_sum += coordination_number(sim);
      ++samples;
    }
  }
  steps += kWindowSteps;
  IsotropicState& iso = sp.isotropic;
  iso.wall_stress = wall_sum / samples;
  iso.love_weber_stress = lw_sum / samples;
  iso.coordination = z_sum / samples;
  iso.max_axis_error = 0.0;
  for (int a = 0; a < 3; ++a)
    iso.max_axis_error = std::max(iso.max_axis_error, std::fabs(iso.wall_stress[a] - sp.confining) / sp.confining);
  iso.solid_fraction = solid_volume(sim) / sp.box.volume(sim);
  iso.void_ratio = 1.0 / iso.solid_fraction - 1.0;
  iso.steps += steps;
}

// The same particles and walls under another particle law (the real law after a dense or an
// in-between compression). Contact histories start empty: without friction they held no
// tangential or rolling spring; after a compression with a preparation friction the tangential
// springs it held are released, and the equilibrium that follows lets the contacts slip into
// the real law's (the density set by the preparation friction is kept: the solid fraction is
// measured after it).
std::unique_ptr<Simulation> with_law(const Simulation& old, const ContactLaw& law) {
  auto sim = std::make_unique<Simulation>(old.particles(), law, old.settings(), old.bodies());
  sim->set_gravity(Vec3{});
  for (Wall w : old.walls()) {
    w.force = Vec3{};
    w.torque = Vec3{};
    w.displacement = Vec3{};
    sim->add_wall(std::move(w));
  }
  return sim;
}

}  // namespace

ElementSpecimen prepare_specimen(const ElementSetup& setup, const Packing& packing, double confining,
                                 const ElementLog& log) {
  if (!(confining > 0.0))
    throw InputError(fmt::format("element test: confining stress {} Pa: expected a stress > 0 (Pa)", confining));
  const ElementSettings& e = setup.settings;
  double side = 0.0;
  Grains gas = random_gas(setup.material.sizes, setup.material.density, setup.material.shape, e.particles,
                          e.gas_solid_fraction, e.seed, side);
  ElementSpecimen sp;
  sp.packing = packing;
  sp.confining = confining;
  sp.sim = std::make_unique<Simulation>(std::move(gas.particles), preparation_law(setup.material.particle, packing),
                                        simulation_settings(setup, side), std::move(gas.bodies));
  sp.sim->set_gravity(Vec3{});  // an element of soil: no body force
  sp.box = add_box_walls(*sp.sim, Vec3{}, Vec3{side, side, side}, frictionless(setup.material.particle));

  // Walls close in at most at the preparation strain rate (each wall at half of it times the side).
  const double rate = preparation_strain_rate(setup, confining);
  const double max_speed = 0.5 * rate * side;
  // The gas is compressed by about 1 - (0.3 / 0.64)^(1/3) = 22 % on each axis: ~0.25 / (rate dt)
  // steps at the cap; twenty times that bounds the whole stage.
  const auto max_steps = static_cast<std::int64_t>(20.0 * 0.25 / (rate * setup.time_step)) + 40 * kWindowSteps;
  if (log)
    log(fmt::format("{} specimen at {:.4g} Pa: {} {}, gas side {:.2f} mm, compression at <= {:.3g} 1/s",
                    to_string(packing), confining, sp.sim->bodies().empty() ? sp.sim->particles().size() : sp.sim->bodies().size(),
                    sp.sim->bodies().empty() ? "particles" : "clumps", side * 1e3, rate));
  equilibrate(sp, setup, max_speed, max_steps, log);
  if (packing.kind != PackingKind::loose) {
    sp.sim = with_law(*sp.sim, setup.material.particle);
    equilibrate(sp, setup, max_speed, max_steps, log);  // adds its steps to the first one's
  }
  if (log)
    log(fmt::format("  isotropic: solid fraction {:.4f} (e = {:.3f}), z = {:.2f}, wall p {:.5g} Pa, Love-Weber p "
                    "{:.5g} Pa, {} steps",
                    sp.isotropic.solid_fraction, sp.isotropic.void_ratio, sp.isotropic.coordination,
                    sp.isotropic.wall_mean(), sp.isotropic.love_weber_mean(), sp.isotropic.steps));
  return sp;
}

SpecimenResult shear_specimen(ElementSpecimen& sp, const ElementSetup& setup, const ElementLog& log,
                              const ShearObserver& observe) {
  Simulation& sim = *sp.sim;
  const ElementSettings& e = setup.settings;
  const bool biaxial = e.kind == ElementTestKind::biaxial;
  SpecimenResult r;
  r.packing = sp.packing;
  r.confining = sp.confining;
  r.isotropic = sp.isotropic;
  r.strain_rate = shear_strain_rate(setup, sp.confining);

  const double h0 = sp.box.length(sim, 2);
  const double v0 = sp.box.volume(sim);
  const double wall_speed = 0.5 * r.strain_rate * h0;
  // The axial walls reach their speed over a ramp of 0.1 % of axial strain (at the full rate it
  // would take half as long). Started at once, they would send a stress wave of about
  // rho c v ~ 1500 kg/m^3 x 800 m/s x 0.045 m/s ~ 50 kPa through the stiff specimen: the lateral
  // servo then missed its target by 1.5 % over the first row (1000-sphere specimens). The ramp
  // spans ~20 wave crossings of such a specimen.
  const double ramp_time = 2.0 * kRampStrain / r.strain_rate;
  auto set_axial_speed = [&](double speed) {
    sim.set_wall_velocity(sp.box.wall[2][0], Vec3{0.0, 0.0, speed});
    sim.set_wall_velocity(sp.box.wall[2][1], Vec3{0.0, 0.0, -speed});
  };
  set_axial_speed(0.0);
  // The lateral walls may move at up to twice the axial rate each (a lateral strain rate of four
  // times the axial one: far above the steepest dilation).
  const double lateral_cap = 2.0 * r.strain_rate * sp.box.length(sim, 0);
  const double response = wall_contact_response(sim, sp.box);
  StressServo servo[2] = {StressServo(sp.confining, lateral_cap, response),
                          StressServo(sp.confining, lateral_cap, response)};
  if (biaxial) {  // plane strain: the y walls stay where the isotropic stage left them
    sim.set_wall_velocity(sp.box.wall[1][0], Vec3{});
    sim.set_wall_velocity(sp.box.wall[1][1], Vec3{});
  }
  const int servo_axes = biaxial ? 1 : 2;
  const auto total_steps = static_cast<std::int64_t>(
      std::ceil((e.max_axial_strain + kRampStrain) / (r.strain_rate * sim.time_step())));
  const double d = setup.material.sizes.mean_diameter();

  // Row accumulators.
  struct Sum {
    double eps_a = 0, eps_v = 0, z = 0;
    Vec3 wall, lw, interior;
    int n = 0, n_sampled = 0, n_interior = 0;
  } sum;
  const double interior_margin = e.interior_margin * setup.material.sizes.mean_diameter();
  // An interior at least a mean diameter wide on every axis; a smaller specimen's rows give NaN.
  auto interior_fits = [&] {
    for (int a = 0; a < 3; ++a)
      if (sp.box.length(sim, a) < 2.0 * interior_margin + d) return false;
    return true;
  };
  double next_row = e.row_strain;
  const double t0 = sim.time();
  bool ramping = true;
  for (std::int64_t step = 0; step < total_steps; ++step) {
    if (ramping) {
      const double fraction = std::min(1.0, (sim.time() - t0 + 0.5 * sim.time_step()) / ramp_time);
      set_axial_speed(fraction * wall_speed);
      ramping = fraction < 1.0;
    }
    sim.step();
    const std::vector<int> contacts = wall_contact_counts(sim);
    for (int a = 0; a < servo_axes; ++a) servo[a].update(sim, sp.box, a, contacts);
    const double eps_a = 1.0 - sp.box.length(sim, 2) / h0;
    if (observe) observe(sim, sp.box, eps_a);
    sum.eps_a += eps_a;
    sum.eps_v += 1.0 - sp.box.volume(sim) / v0;
    sum.wall += wall_stress(sim, sp.box);
    ++sum.n;
    if (step % kStressSampleEvery == 0) {
      sum.lw += diagonal(love_weber_stress(sim, sp.box));
      sum.z += coordination_number(sim);
      ++sum.n_sampled;
    }
    if (step % kInteriorSampleEvery == 0 && interior_fits()) {
      sum.interior += diagonal(interior_contact_stress(sim, sp.box, interior_margin));
      ++sum.n_interior;
    }
    const bool last = step + 1 == total_steps || eps_a >= e.max_axial_strain;
    if (eps_a >= next_row || last) {
      ElementRow row;
      row.axial_strain = sum.eps_a / sum.n;
      row.volumetric_strain = sum.eps_v / sum.n;
      row.wall_stress = sum.wall / sum.n;
      row.love_weber_stress = sum.n_sampled > 0 ? sum.lw / sum.n_sampled : Vec3{};
      row.coordination = sum.n_sampled > 0 ? sum.z / sum.n_sampled : 0.0;
      const double axial = row.wall_stress.z;
      const double lateral = biaxial ? row.wall_stress.x : 0.5 * (row.wall_stress.x + row.wall_stress.y);
      row.deviator = axial - lateral;
      row.mean_stress = (row.wall_stress.x + row.wall_stress.y + row.wall_stress.z) / 3.0;
      row.sin_phi = (axial - lateral) / (axial + lateral);
      row.interior_stress = Vec3{NAN, NAN, NAN};
      row.interior_sin_phi = NAN;
      if (sum.n_interior > 0) {
        row.interior_stress = sum.interior / sum.n_interior;
        const double in_axial = row.interior_stress.z;
        const double in_lateral =
            biaxial ? row.interior_stress.x : 0.5 * (row.interior_stress.x + row.interior_stress.y);
        row.interior_sin_phi = (in_axial - in_lateral) / (in_axial + in_lateral);
      }
      row.inertial_number = r.strain_rate * d / std::sqrt(std::max(row.mean_stress, 1e-300) / setup.material.density);
      for (int a = 0; a < servo_axes; ++a)
        row.lateral_error = std::max(row.lateral_error, std::fabs(row.wall_stress[a] - sp.confining) / sp.confining);
      r.rows.push_back(row);
      sum = Sum{};
      next_row += e.row_strain;
      if (log && r.rows.size() % 20 == 0)
        log(fmt::format("  {} {:.0f} Pa: axial strain {:5.1f} %, sin phi {:.3f} ({:.1f} deg), volumetric {:+.2f} %, z "
                        "{:.2f}, I {:.2g}",
                        to_string(sp.packing), sp.confining, 100.0 * row.axial_strain, row.sin_phi,
                        std::asin(std::clamp(row.sin_phi, -1.0, 1.0)) * kDegree, 100.0 * row.volumetric_strain,
                        row.coordination, row.inertial_number));
      if (last) break;
    }
  }
  summarise_specimen(r, e.critical_state_window);
  if (log)
    log(fmt::format("  {} {:.0f} Pa: phi'_peak {:.1f} deg at {:.1f} %, phi'_cs {:.1f} deg (+-{:.1f}), psi at peak "
                    "{:.1f} deg, lateral stress within {:.2f} %",
                    to_string(sp.packing), sp.confining, r.phi_peak, 100.0 * r.axial_strain_at_peak, r.phi_cs,
                    r.phi_cs_scatter, r.psi_peak, 100.0 * r.max_lateral_error));
  return r;
}

void summarise_specimen(SpecimenResult& r, double window) {
  if (r.rows.empty()) return;
  auto angle = [](double s) { return std::asin(std::clamp(s, -1.0, 1.0)) * kDegree; };
  std::size_t peak = 0;
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    if (r.rows[k].sin_phi > r.rows[peak].sin_phi) peak = k;
    r.max_lateral_error = std::max(r.max_lateral_error, r.rows[k].lateral_error);
  }
  r.phi_peak = angle(r.rows[peak].sin_phi);
  r.axial_strain_at_peak = r.rows[peak].axial_strain;

  const double end = r.rows.back().axial_strain;
  double s_sum = 0.0, interior_sum = 0.0;
  std::vector<double> angles;
  for (const ElementRow& row : r.rows) {
    if (row.axial_strain < end - window) continue;
    s_sum += row.sin_phi;
    interior_sum += row.interior_sin_phi;
    angles.push_back(angle(row.sin_phi));
  }
  r.phi_cs = angle(s_sum / double(angles.size()));
  r.phi_cs_interior = angle(interior_sum / double(angles.size()));
  double m = 0.0, m2 = 0.0;
  for (double a : angles) m += a;
  m /= double(angles.size());
  for (double a : angles) m2 += (a - m) * (a - m);
  r.phi_cs_scatter = angles.size() > 1 ? std::sqrt(m2 / double(angles.size() - 1)) : 0.0;

  // Least-squares slope of eps_v against eps_a over +-1 % around the peak.
  const double at = r.axial_strain_at_peak;
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  int n = 0;
  for (const ElementRow& row : r.rows) {
    if (std::fabs(row.axial_strain - at) > 0.01) continue;
    sx += row.axial_strain;
    sy += row.volumetric_strain;
    sxx += row.axial_strain * row.axial_strain;
    sxy += row.axial_strain * row.volumetric_strain;
    ++n;
  }
  const double denominator = n * sxx - sx * sx;
  if (n >= 2 && denominator > 0.0) {
    const double slope = (n * sxy - sx * sy) / denominator;  // d eps_v / d eps_1
    r.psi_peak = angle(-slope / (2.0 - slope));
  } else {
    r.psi_peak = std::nan("");
  }
}

ElementResult run_element_test(const ElementSetup& setup, const ElementLog& log) {
  ElementResult result;
  result.name = setup.name;
  result.settings = setup.settings;
  result.mean_diameter = setup.material.sizes.mean_diameter();
  result.time_step = setup.time_step;
  for (double confining : setup.settings.confining) {
    for (const Packing& packing : setup.settings.packings) {
      ElementSpecimen sp = prepare_specimen(setup, packing, confining, log);
      result.specimens.push_back(shear_specimen(sp, setup, log));
    }
  }
  return result;
}

}  // namespace trapdem
