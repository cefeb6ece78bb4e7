#include "experiment/experiment_config.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "core/thread_count.hpp"
#include "dem/rigid/rigid_bodies.hpp"
#include "experiment/centrifuge_frame.hpp"
#include "experiment/packing_input.hpp"
#include "io/config.hpp"

namespace trapdem {

namespace {

// Upper bounds set by physics or memory (docs/config.md states each in its key's row). A value
// beyond them is a typo or a unit slip (mm written as m), never an experiment this program can run.
constexpr double kMaxLength = 10.0;            // m: box, trapdoor, travel, heights; strongboxes are < 2 m
constexpr double kMaxDiameter = 1.0;           // m
constexpr double kMaxDensity = 1e5;            // kg/m^3: the densest solid (osmium) is 22 590
constexpr double kMaxRate = 10.0;              // m/s: a trapdoor lowered faster is no longer quasi-static
constexpr std::int64_t kMaxParticles = 100'000'000;  // memory: about 0.5 kB per particle with its contacts
constexpr double kMaxTime = 1e4;               // s of simulated time in one stage
constexpr double kMaxGLevel = 1000.0;          // g: centrifuges reach a few hundred g
constexpr double kMaxDropHeight = 100.0;       // m
constexpr double kMaxFlowRate = 1e4;           // kg/s
constexpr double kMaxSkinFraction = 2.0;       // of the largest diameter: a larger skin lists ~100x the pairs
constexpr double kMaxWallClock = 1e7;          // s (116 days) between checkpoints or progress lines
constexpr double kMaxSteps = 1e11;             // time steps of one stage: years of computing
constexpr double kMaxRows = 1e7;               // trapdoor.csv rows
constexpr std::size_t kMaxSnapshots = 10'000;  // output.snapshot_displacements entries
constexpr double kMaxCentrifugeRadius = 20.0;  // m: the largest geotechnical centrifuges have arms of about 10 m
constexpr double kMaxSpinRate = 150.0;         // rad/s (1430 rpm): the fastest (mini drums, ~0.4 m) turn at ~1100 rpm

// A contact law's keys, with defaults taken from `base` (the particle law for the walls). The
// normal model's own keys: normal_stiffness and tangential_stiffness for "linear"; for "hertz",
// youngs_modulus (required unless inherited) and poisson_ratio. A stiffness key under "hertz" is
// an error (it would be ignored); youngs_modulus and poisson_ratio describe the body's material
// and are accepted with either (a Hertz wall reads the particles' material from [contact]).
// The law's choices from the table, then every model's parameters as the models declare them
// (contact/law_parameter.hpp): the chosen models' with their bounds, required when the base law has
// no valid value (a Young's modulus for Hertz, Blaze-DEM's time step); a material's (E, nu) always;
// another model's key refused when it is exclusive to that model (its value would be ignored), else
// read with its bounds and kept (a preset's friction under a law that does not use it), and noted in
// `unread` ("<table>.<key> (read only with ...)") for run.log.
ContactLaw read_contact_law(Config table, const std::string& table_name, const ContactLaw& base,
                            std::vector<std::string>& unread) {
  ContactLaw law = base;
  law.normal_model = parse_choice<NormalModel>(
      table.get_choice("normal_model", to_string(base.normal_model), choice_names<NormalModel>()));
  law.damping_model = parse_choice<DampingModel>(
      table.get_choice("damping_model", to_string(base.damping_model), choice_names<DampingModel>()));
  law.tangential_model = parse_choice<TangentialModel>(
      table.get_choice("tangential_model", to_string(base.tangential_model), choice_names<TangentialModel>()));
  law.rolling_model = parse_choice<RollingModel>(
      table.get_choice("rolling_model", to_string(base.rolling_model), choice_names<RollingModel>()));
  law.lever_arm = parse_choice<RollingLeverArm>(
      table.get_choice("lever_arm", to_string(base.lever_arm), choice_names<RollingLeverArm>()));
  law.rolling_stiffness = parse_choice<RollingStiffness>(
      table.get_choice("rolling_stiffness", to_string(base.rolling_stiffness), choice_names<RollingStiffness>()));

  const std::vector<LawParameter> declared = declared_parameters();
  const std::vector<LawParameter> chosen = chosen_parameters(law);
  auto find = [](const std::vector<LawParameter>& list, std::string_view key) -> const LawParameter* {
    for (const LawParameter& p : list)
      if (p.key == key) return &p;
    return nullptr;
  };
  for (const LawParameter& any : declared) {
    const LawParameter* mine = find(chosen, any.key);
    const LawParameter& p = mine ? *mine : any;
    // Active: read by a model that is on (rolling_friction, read first, says whether rolling is).
    const bool active = find(active_parameters(law), p.key) != nullptr;
    if (!active && !p.material && p.exclusive) {
      if (table.has(p.key))
        table.fail(p.key, fmt::format("no {} with this law (read only with {}); remove the key", p.key, readers_of(p.key)));
      continue;
    }
    // Read within the widest bounds any model gives the key; a chosen model's narrower ones are its
    // rule, checked after (so that a value past them still says whether a model is on).
    const Range range{any.bounds.lowest, any.bounds.highest, any.bounds.lowest_included, any.bounds.highest_included};
    double fallback = base.*p.field;
    if (!p.follows.empty() && table.has(p.follows)) fallback = p.follow_factor * law.*find(declared, p.follows)->field;
    // Every key read is written to resolved.toml with its value; an unset one with no valid value
    // (a Young's modulus of 0 under the linear law) is not read, so none is written back.
    if (active && !table.has(p.key) && !p.bounds.contain(fallback))
      law.*p.field = table.require_double(p.key, p.unit, range);
    else if (table.has(p.key) || p.bounds.contain(fallback))
      law.*p.field = table.get_double(p.key, fallback, p.unit, range);
    else
      law.*p.field = fallback;
    if (table.has(p.key) && any.bounds.contain(law.*p.field) && !p.bounds.contain(law.*p.field))
      table.fail(p.key, p.meaning);
    // Noted when no model that is on reads it, once its value is in (the rolling switch, first in
    // the list, is read by the rolling model it turns off).
    const bool switch_of_chosen = mine && p.key == declared.front().key;
    if (table.has(p.key) && !p.material && !switch_of_chosen && !find(active_parameters(law), p.key))
      unread.push_back(fmt::format("{}.{} (read only with {})", table_name, p.key, readers_of(p.key)));
  }
  return law;
}

SizeDistribution read_sizes(Config& p) {
  const std::string kind = p.get_choice("size", "single", {"single", "uniform", "grading"});
  if (kind == "single") return SizeDistribution::single(p.get_double("diameter", 0.002, "m", Range::open_closed(0.0, kMaxDiameter)));
  if (kind == "uniform") {
    const double lo = p.require_double("min_diameter", "m", Range::open_closed(0.0, kMaxDiameter));
    const double hi = p.require_double("max_diameter", "m", Range::open_closed(0.0, kMaxDiameter));
    if (!(lo > 0.0) || !(hi > 0.0)) return SizeDistribution::single(0.002);  // refused and recorded: read on
    if (hi < lo) p.fail("max_diameter", fmt::format("a size >= min_diameter ({} m)", lo));
    return SizeDistribution::uniform(lo, std::max(lo, hi));
  }
  std::vector<std::pair<double, double>> table;
  for (const auto& row : p.require_rows("grading", 2, "diameter in m, percent passing")) table.emplace_back(row[0], row[1]);
  try {
    return SizeDistribution::grading(std::move(table), "grading");
  } catch (const InputError& e) {
    p.fail("grading", e.what());  // names the file and line of the table
    return SizeDistribution::single(0.002);  // reading goes on to find the other errors
  }
}

// The specimen's identity, box and trapdoor (from() and specimen_from() read them alike).
void read_specimen(Config& c, ExperimentConfig& e) {
  e.name = c.get_string("name", "trapdoor");
  e.description = c.get_string("description", "");

  Config box = c.get_table("box");
  e.box.width = box.get_double("width", e.box.width, "m", Range::open_closed(0.0, kMaxLength));
  e.box.depth = box.get_double("depth", e.box.depth, "m", Range::open_closed(0.0, kMaxLength));
  e.box.height = box.get_double("height", e.box.height, "m", Range::open_closed(0.0, kMaxLength));
  e.box.periodic_depth = box.get_choice("depth_boundary", "walls", {"walls", "periodic"}) == "periodic";

  Config door = c.get_table("trapdoor");
  e.trapdoor.width = door.get_double("width", e.trapdoor.width, "m", Range::open_closed(0.0, kMaxLength));
  if (e.trapdoor.width >= e.box.width)
    door.fail("width", fmt::format("a trapdoor narrower than the box (box.width = {} m)", e.box.width));
  e.trapdoor.centre = door.get_double("centre", 0.5 * e.box.width, "m", Range::open_closed(0.0, kMaxLength));
  if (e.trapdoor.centre - 0.5 * e.trapdoor.width <= 0.0 || e.trapdoor.centre + 0.5 * e.trapdoor.width >= e.box.width)
    door.fail("centre", fmt::format("a position that keeps the trapdoor inside the box (0 .. {} m) with "
                                           "fixed base on both sides", e.box.width));
  e.trapdoor.travel = door.get_double("travel", e.trapdoor.travel, "m", Range::open_closed(0.0, kMaxLength));
  e.trapdoor.rate = door.get_double("rate", e.trapdoor.rate, "m/s", Range::open_closed(0.0, kMaxRate));
  e.trapdoor.cavity_depth = door.get_double("cavity_depth", e.trapdoor.travel + 0.01, "m", Range::open_closed(0.0, kMaxLength));
  if (e.trapdoor.cavity_depth < e.trapdoor.travel)
    door.fail("cavity_depth", fmt::format("at least the travel ({} m)", e.trapdoor.travel));
}

// pluviation.fill_height: the pour's end, and the soil height the sinkhole estimate falls back on.
double read_fill_height(Config& pour, const BoxConfig& box) {
  const double fill_height = pour.get_double("fill_height", 0.0, "m", Range::non_negative());
  if (fill_height > box.height) pour.fail("fill_height", fmt::format("at most the box height ({} m)", box.height));
  return fill_height;
}

// [packing]: read only when the table is there, so that a run that pours records no packing key
// (and its resume identity is what it was).
void read_packing_keys(Config& c, PackingConfig& p) {
  if (!c.has("packing")) return;
  Config t = c.get_table("packing");
  p.from = t.require_path("from");  // relative: from the configuration file's folder (--set: the working folder)
  if (t.has("from") && p.from.empty()) t.fail("from", "the path of a packing file, or of a trapdem run folder");
  const std::vector<std::string> formats = {"lammps-data", "lammps-dump", "trapdem"};
  if (t.has("format")) p.format = t.get_choice("format", "lammps-data", formats);
  else t.fail("format", "a format for packing.from: \"lammps-data\", \"lammps-dump\" or \"trapdem\"");
  if (t.has("snapshot")) {
    if (p.format == "trapdem") p.snapshot = t.get_int("snapshot", 0, Range::closed(0.0, double(kMaxSnapshots)));
    else t.fail("snapshot", "no snapshot index with this format (packing.snapshot picks a snapshot of format = \"trapdem\")");
  }
  const std::vector<double> shift = t.get_vector<double>("shift", {0.0, 0.0, 0.0}, "m", Range::closed(-kMaxLength, kMaxLength));
  if (shift.size() == 3) p.shift = {shift[0], shift[1], shift[2]};
  else t.fail("shift", fmt::format("three numbers [dx, dy, dz] in m (found {})", shift.size()));
  p.start_at_spin_up = t.get_choice("start_stage", "settling", {"settling", "spin_up"}) == "spin_up";
}

// The packing file read and checked (after its keys passed): the sizes the box's margins, skin
// and time step are derived from become the packing's, and the critical step its smallest.
void load_packing(Config& c, ExperimentConfig& e) {
  PackingParticles read =
      read_packing(e.packing, e.box, e.material.density, e.numerics.max_overlap_fraction, e.material.shape);
  const Particles& p = read.particles;
  const RigidBodies& bodies = read.bodies;
  double critical = std::numeric_limits<double>::infinity();
  double d_lo = std::numeric_limits<double>::infinity(), d_hi = 0.0;  // m, the grains' (volume-equivalent) diameters
  if (bodies.empty()) {
    for (std::size_t i = 0; i < p.size(); ++i) {
      d_lo = std::min(d_lo, 2.0 * p.radius[i]);
      d_hi = std::max(d_hi, 2.0 * p.radius[i]);
      critical = std::min(critical, trapdem::critical_time_step(e.material.particle, e.material.wall_laws(), p.mass[i],
                                                                p.radius[i]));
    }
  } else {  // as Simulation::critical_time_step
    for (std::size_t b = 0; b < bodies.size(); ++b) {
      const double d = std::cbrt(6.0 * bodies.volume[b] / std::numbers::pi);
      d_lo = std::min(d_lo, d);
      d_hi = std::max(d_hi, d);
      const BodyContactScale scale = body_contact_scale(bodies, p, b);
      critical = std::min(critical, trapdem::critical_time_step(e.material.particle, e.material.wall_laws(), scale.mass,
                                                                scale.smallest_radius));
    }
    e.packing.bodies = std::make_shared<const RigidBodies>(std::move(read.bodies));
  }
  e.material.sizes = d_lo == d_hi ? SizeDistribution::single(d_lo) : SizeDistribution::uniform(d_lo, d_hi);
  e.packing.critical_time_step = critical;
  e.packing.particles = std::make_shared<const Particles>(std::move(read.particles));
  if (e.numerics.time_step > critical)
    throw c.error("numerics.time_step", fmt::format("a step at most the packing's critical step {} = {:.4g} s",
                                                    critical_time_step_formula(e.material.particle, e.material.wall_laws()),
                                                    critical));
}

// A periodic depth holds at least twice the interaction range, the largest diameter plus the skin
// (the engine's own check, at every list build): a pour skin larger than the run's that it does
// not hold is an error here, naming the key, not at the pour's first list build.
void check_pour_skin_against_the_period(Config& pour, const ExperimentConfig& e) {
  if (!e.box.periodic_depth || e.pour_skin() <= e.skin()) return;
  const double d = e.material.sizes.max_diameter();
  const double widest = 0.5 * e.box.depth - d;  // m
  if (e.pour_skin() < widest) return;
  pour.fail("skin_fraction",
            fmt::format("a pour skin the periodic depth holds: box.depth = {:.4g} mm must be more than twice the "
                        "largest diameter plus the skin, so less than {:.3g} of the largest diameter ({:.4g} mm) here",
                        e.box.depth * 1e3, widest / d, d * 1e3));
}

// m, the height of the deposit pluviation.count particles make at pluviation.packing_fraction.
double count_deposit_height(const ExperimentConfig& e) {
  const double d = e.material.sizes.mean_diameter();
  return double(e.pluviation.count) * std::numbers::pi / 6.0 * d * d * d /
         (e.pluviation.packing_fraction * e.box.width * e.box.depth);
}

// particles.density (kg/m^3): from() and specimen_from() read it alike.
double read_density(Config& particles, double fallback) {
  return particles.get_double("density", fallback, "kg/m^3", Range::open_closed(0.0, kMaxDensity));
}

// [centrifuge]: read only when the table is there, so that a run in uniform gravity records no
// centrifuge key (and its resume identity is what it was). The model's height is the fill height,
// else the deposit of the count; a packing's top replaces it once the packing is read.
void read_centrifuge(Config& c, ExperimentConfig& e) {
  if (!c.has("centrifuge")) return;
  Config t = c.get_table("centrifuge");
  CentrifugeConfig& f = e.centrifuge;
  f.enabled = true;
  f.radius = t.require_double("radius", "m", Range::open_closed(0.0, kMaxCentrifugeRadius));
  f.reference = t.get_choice("reference", f.reference, {"base", "surface", "effective"});
  f.width_in_plane = t.get_choice("width_orientation", "in_plane", {"in_plane", "normal"}) == "in_plane";
  f.coriolis = t.get_bool("coriolis", f.coriolis);
  f.euler = t.get_bool("euler", f.euler);
  f.model_height = e.pluviation.fill_height > 0.0 ? e.pluviation.fill_height
                   : e.pluviation.count > 0       ? count_deposit_height(e)
                                                  : e.box.height;
}

// The frame must fit the model and be a centrifuge's: the axis above the box, a spin rate a
// centrifuge reaches, and a spin-up whose Euler force does not rival the weight.
void check_centrifuge(Config& c, const ExperimentConfig& e) {
  const CentrifugeConfig& f = e.centrifuge;
  if (!f.enabled || !(f.radius > 0.0)) return;
  if (!(f.radius > f.model_height))
    return c.fail("centrifuge.radius",
                  fmt::format("a radius larger than the model's height ({:.4g} m): the axis would be inside the model",
                              f.model_height));
  const double axis_height = f.reference_height() + f.radius;
  if (!(axis_height > e.box.height))
    return c.fail("centrifuge.radius",
                  fmt::format("a radius that puts the axis above the box's top ({:.4g} m): with reference = \"{}\" "
                              "at {:.4g} m above the base the axis is {:.4g} m above it",
                              e.box.height, f.reference, f.reference_height(), axis_height));
  const double w1 = centrifuge_angular_velocity(1.0, f.radius);
  const double wn = centrifuge_angular_velocity(e.spin_up.g_level, f.radius);
  if (wn > kMaxSpinRate)
    return c.fail("spin_up.g_level",
                  fmt::format("a g level a centrifuge of radius {} m reaches: {:g} g there needs {:.4g} rad/s ({:.0f} "
                              "rpm), above {:g} rad/s (the fastest geotechnical centrifuges turn at ~1100 rpm)",
                              f.radius, e.spin_up.g_level, wn, wn * 60.0 / (2.0 * std::numbers::pi), kMaxSpinRate));
  if (f.euler) {
    // alpha r at the reference radius at most 1 g: the weight the spin-up starts from.
    const double min_ramp = (wn - w1) * f.radius / ExperimentConfig::standard_gravity;
    if (e.spin_up.ramp_time < min_ramp)
      c.fail("spin_up.ramp_time",
             fmt::format("a ramp of at least {:.4g} s with centrifuge.euler = true: the spin-up's Euler acceleration "
                         "alpha r at the reference radius must stay below 1 g (a real spin-up takes minutes and "
                         "gives ~0.01 g); or centrifuge.euler = false for a quasi-static spin-up",
                         min_ramp));
  }
}

// What resolved.toml records of the frame beyond its keys.
void add_centrifuge_derived(Config& c, const ExperimentConfig& e) {
  const CentrifugeConfig& f = e.centrifuge;
  if (!f.enabled) return;
  const double g = ExperimentConfig::standard_gravity;
  const double w = centrifuge_angular_velocity(e.spin_up.g_level, f.radius);
  const double r_surface = centrifuge_radius_at(f, f.model_height), r_base = centrifuge_radius_at(f, 0.0);
  c.add_derived("derived.centrifuge_model_height", f.model_height, "m");
  c.add_derived("derived.centrifuge_reference_height", f.reference_height(), "m");
  c.add_derived("derived.centrifuge_angular_velocity", w, "rad/s");
  c.add_derived("derived.centrifuge_radius_surface", r_surface, "m");
  c.add_derived("derived.centrifuge_radius_base", r_base, "m");
  c.add_derived("derived.centrifuge_g_level_surface", w * w * r_surface / g, "g");
  c.add_derived("derived.centrifuge_g_level_base", w * w * r_base / g, "g");
  const double half_span = 0.5 * (f.width_in_plane ? e.box.width : e.box.depth);
  c.add_derived("derived.centrifuge_side_tilt", std::atan2(half_span, r_base) * 180.0 / std::numbers::pi, "degrees");
  if (f.euler && e.spin_up.ramp_time > 0.0) {
    const double alpha = (w - centrifuge_angular_velocity(1.0, f.radius)) / e.spin_up.ramp_time;
    c.add_derived("derived.centrifuge_euler_acceleration", alpha * f.radius, "m/s^2");
  }
}

double read_g_level(Config& spin, const SpinUpConfig& defaults) {
  return spin.get_double("g_level", defaults.g_level, "g", Range::closed(1.0, kMaxGLevel));
}

// The key behind the critical time step: the stiffness (linear) or Young's modulus (Hertz) of the
// law with the shortest contact time scale.
std::string stiffest_key(const ExperimentConfig& e) {
  const double r = 0.5 * e.material.sizes.min_diameter();
  const double m = e.material.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const std::pair<const ContactLaw*, const char*> laws[] = {{&e.material.particle, "contact"},
                                                            {&e.material.base, "walls.base"},
                                                            {&e.material.front, "walls.front"},
                                                            {&e.material.back, "walls.back"}};
  std::size_t stiffest = 0;
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < std::size(laws); ++k) {
    const double t = contact_time_scale(*laws[k].first, e.material.particle, m, r);
    if (t < shortest || std::isnan(t)) {
      shortest = t;
      stiffest = k;
    }
  }
  const ContactLaw& law = *laws[stiffest].first;
  return fmt::format("{}.{}", laws[stiffest].second, stiffness_parameter(law).key);
}

// The time step derived from the keys must be a usable number: a denormal stiffness (1e-320 N/m)
// passes "> 0" and gives sqrt(m/k) = inf; a huge one with tiny particles gives a step below what
// a double resolves against the simulated time.
void check_time_step(Config& c, const ExperimentConfig& e) {
  const double critical = e.critical_time_step();
  if (!std::isfinite(critical) || !(critical > 0.0))
    return c.fail(stiffest_key(e), fmt::format("a value that gives a finite critical time step ({} = {} s with the "
                                               "density and smallest diameter given)",
                                               critical_time_step_formula(e.material.particle, e.material.wall_laws()),
                                               critical));
  if (!(e.time_step() >= 1e-15))
    return c.fail(e.numerics.time_step > 0.0 ? "numerics.time_step"
                  : critical >= 1e-15       ? "numerics.time_step_fraction"
                                            : stiffest_key(e),
                  fmt::format("a time step of at least 1e-15 s (it is {:.4g} s)", e.time_step()));
}

// Each stage's steps, from the simulated times and the time step: a count beyond kMaxSteps would
// run for years (and its step counter would lose exactness in the progress estimates).
void check_step_counts(Config& c, const ExperimentConfig& e) {
  const double dt = e.time_step();
  const std::pair<const char*, double> stages[] = {
      {"settling.max_time", e.settling.max_time},
      {"spin_up.ramp_time", e.spin_up.ramp_time + e.settling.max_time},
      {"trapdoor.rate", e.trapdoor.travel / e.trapdoor.rate},
  };
  for (const auto& [key, seconds] : stages) {
    if (seconds / dt > kMaxSteps)
      return c.fail(key, fmt::format("a stage of at most {:g} time steps: {:.4g} s of simulated time at dt = {:.4g} s "
                                     "is {:.3g} steps", kMaxSteps, seconds, dt, seconds / dt));
  }
  if (e.pluviation.count == 0) {
    const double d = e.material.sizes.mean_diameter();
    const double expected = e.pluviation.packing_fraction * e.box.width * e.box.depth * e.pluviation.fill_height /
                            (std::numbers::pi / 6.0 * d * d * d);
    if (!(expected <= double(kMaxParticles)))
      c.fail("pluviation.fill_height", fmt::format("a fill height that needs at most {} particles (memory: about "
                                                          "0.5 kB each); it needs {:.3g}", kMaxParticles, expected));
  }
}

}  // namespace

ExperimentConfig ExperimentConfig::from(Config& c) {
  c.collect_errors();
  ExperimentConfig e;
  read_specimen(c, e);

  Config particles = c.get_table("particles");
  e.material.density = read_density(particles, e.material.density);
  e.material.sizes = read_sizes(particles);
  Config shape = particles.get_table("shape");
  e.material.shape = read_particle_shape(shape);
  if (e.material.shape.is_clump()) {
    if (e.box.periodic_depth)
      shape.fail("kind", "spheres with box.depth_boundary = \"periodic\" (clumps need walls on every side: a "
                         "clump's members would straddle the periodic boundary)");
  }
  if (e.material.sizes.max_diameter() * 3.0 > e.box.depth && !e.box.periodic_depth) {
    const char* size_key = particles.has("grading") ? "grading" : (particles.has("max_diameter") ? "max_diameter" : "diameter");
    particles.fail(size_key, fmt::format("particles at most a third of the box depth ({} m)", e.box.depth));
  }

  Config contact = c.get_table("contact");
  std::vector<std::string>& unread = e.material.unread_parameters;
  e.material.particle = read_contact_law(contact, "contact", ContactLaw{}, unread);
  Config walls = c.get_table("walls");
  e.material.base = read_contact_law(walls.get_table("base"), "walls.base", e.material.particle, unread);
  e.material.front = read_contact_law(walls.get_table("front"), "walls.front", e.material.base, unread);
  e.material.back = read_contact_law(walls.get_table("back"), "walls.back", e.material.base, unread);
  for (const ContactLaw* law : e.material.wall_laws()) {
    // A Hertz wall contact combines the wall's material with the particles'.
    if (combines_materials(*law) && !(e.material.particle.youngs_modulus > 0.0))
      contact.fail("youngs_modulus", fmt::format("the particles' Young's modulus in Pa: a wall has normal_model = \"{}\"",
                                                 to_string(law->normal_model)));
  }

  read_packing_keys(c, e.packing);
  Config pour = c.get_table("pluviation");
  e.pluviation.count = pour.get_int("count", 0, Range::closed(0.0, double(kMaxParticles)));
  e.pluviation.fill_height = read_fill_height(pour, e.box);
  if (e.pluviation.count == 0 && e.pluviation.fill_height == 0.0 && !c.has("packing"))
    pour.fail("count", "a particle count or a fill_height (m) to end the pour, or a [packing] to start from");
  e.pluviation.drop_height = pour.get_double("drop_height", e.pluviation.drop_height, "m", Range::closed(0.0, kMaxDropHeight));
  e.pluviation.flow_rate = pour.get_double("flow_rate", 0.0, "kg/s", Range::closed(0.0, kMaxFlowRate));
  e.pluviation.packing_fraction =
      pour.get_double("packing_fraction", e.pluviation.packing_fraction, "", Range::open_closed(0.0, 0.75));
  e.pluviation.seed = static_cast<std::uint64_t>(pour.get_int("seed", 1, Range::non_negative()));
  e.pluviation.skin_fraction =
      pour.get_double("skin_fraction", e.pluviation.skin_fraction, "", Range::closed(0.0, kMaxSkinFraction));
  if (e.pluviation.count > 0) {
    // The deposit's height at the assumed solid fraction must fit in the box.
    const double height = count_deposit_height(e);
    if (height > e.box.height)
      pour.fail("count", fmt::format("a count whose deposit fits the box: {} particles at a solid fraction of "
                                            "{} stand {:.1f} mm high, the box is {:.1f} mm",
                                            e.pluviation.count, e.pluviation.packing_fraction, height * 1e3,
                                            e.box.height * 1e3));
  }

  Config settle = c.get_table("settling");
  e.settling.energy_ratio = settle.get_double("energy_ratio", e.settling.energy_ratio, "", Range::open_closed(0.0, 1.0));
  e.settling.min_time = settle.get_double("min_time", e.settling.min_time, "s", Range::closed(0.0, kMaxTime));
  e.settling.max_time = settle.get_double("max_time", e.settling.max_time, "s", Range::open_closed(0.0, kMaxTime));
  if (e.settling.min_time > e.settling.max_time)
    settle.fail("min_time", fmt::format("at most max_time ({} s)", e.settling.max_time));

  Config spin = c.get_table("spin_up");
  e.spin_up.g_level = read_g_level(spin, e.spin_up);
  e.spin_up.ramp_time = spin.get_double("ramp_time", e.spin_up.ramp_time, "s", Range::closed(0.0, kMaxTime));
  read_centrifuge(c, e);

  Config num = c.get_table("numerics");
  e.numerics.time_step = num.get_double("time_step", 0.0, "s", Range::non_negative());
  e.numerics.time_step_fraction =
      num.get_double("time_step_fraction", e.numerics.time_step_fraction, "", Range::open_closed(0.0, 1.0));
  e.numerics.skin_fraction = num.get_double("skin_fraction", e.numerics.skin_fraction, "", Range::open_closed(0.0, kMaxSkinFraction));
  e.numerics.max_overlap_fraction =
      num.get_double("max_overlap_fraction", e.numerics.max_overlap_fraction, "", Range::open_closed(0.0, 1.0));
  e.numerics.threads = static_cast<int>(num.get_int("threads", 0, Range::closed(0.0, kMaxThreads)));
  check_pour_skin_against_the_period(pour, e);

  Config out = c.get_table("output");
  e.output.snapshot_displacements =
      out.get_vector<double>("snapshot_displacements", e.output.snapshot_displacements, "m", Range::closed(0.0, kMaxLength));
  if (e.output.snapshot_displacements.size() > kMaxSnapshots)
    out.fail("snapshot_displacements", fmt::format("at most {} snapshots", kMaxSnapshots));
  std::sort(e.output.snapshot_displacements.begin(), e.output.snapshot_displacements.end());
  e.output.ground_reaction_step =
      out.get_double("ground_reaction_step", e.output.ground_reaction_step, "m", Range::open_closed(0.0, kMaxLength));
  e.output.checkpoint_interval =
      out.get_double("checkpoint_interval", e.output.checkpoint_interval, "s", Range::open_closed(0.0, kMaxWallClock));
  e.output.log_interval = out.get_double("log_interval", e.output.log_interval, "s", Range::open_closed(0.0, kMaxWallClock));
  if (e.trapdoor.travel / e.output.ground_reaction_step > kMaxRows)
    out.fail("ground_reaction_step", fmt::format("a step that gives at most {:g} rows of trapdoor.csv over the "
                                                        "travel of {} m", kMaxRows, e.trapdoor.travel));

  // What is derived from several keys is checked once they are all valid (a time step from a
  // refused stiffness would only repeat that refusal).
  if (!c.has_errors()) check_time_step(c, e);
  if (!c.has_errors() && e.numerics.time_step > e.critical_time_step())
    num.fail("time_step", fmt::format("a step at most the critical step {} = {:.4g} s",
                                      critical_time_step_formula(e.material.particle, e.material.wall_laws()),
                                      e.critical_time_step()));
  if (!c.has_errors()) check_step_counts(c, e);
  if (!c.has_errors() && !e.packing.enabled()) check_centrifuge(c, e);
  c.throw_errors();  // unknown keys, wrong values, broken rules: all of them, in that order
  if (e.packing.enabled()) {
    load_packing(c, e);
    c.add_derived("derived.packing_particle_count", std::int64_t(e.packing.particles->size()));
    if (e.centrifuge.enabled) {  // the model is the packing: its top
      const Particles& p = *e.packing.particles;
      double top = 0.0;
      for (std::size_t i = 0; i < p.size(); ++i) top = std::max(top, p.position[i].z + p.radius[i]);
      e.centrifuge.model_height = top;
      check_centrifuge(c, e);
      c.throw_errors();
    }
  }
  add_centrifuge_derived(c, e);
  c.add_derived("derived.critical_time_step", e.critical_time_step(), "s");
  c.add_derived("derived.time_step", e.time_step(), "s");
  c.add_derived("derived.skin", e.skin(), "m");
  if (!e.packing.particles) c.add_derived("derived.pour_skin", e.pour_skin(), "m");
  c.add_derived("derived.expected_particle_count", e.expected_particle_count());
  c.add_derived("derived.mean_diameter", e.material.sizes.mean_diameter(), "m");
  return e;
}

ExperimentConfig ExperimentConfig::specimen_from(Config& c) {
  ExperimentConfig e;
  read_specimen(c, e);
  Config pour = c.get_table("pluviation");
  e.pluviation.fill_height = read_fill_height(pour, e.box);
  Config spin = c.get_table("spin_up");
  e.spin_up.g_level = read_g_level(spin, e.spin_up);
  // The weight the deposit is under (trapdem deposit): the solid's density and the frame. A run's
  // resolved.toml records the model height its frame used (a packing's top, for a run from one).
  Config particles = c.get_table("particles");
  e.material.density = read_density(particles, e.material.density);
  read_centrifuge(c, e);
  if (e.centrifuge.enabled && c.has("derived")) {
    Config derived = c.get_table("derived");
    e.centrifuge.model_height =
        derived.get_double("centrifuge_model_height", e.centrifuge.model_height, "m", Range::open_closed(0.0, kMaxLength));
  }
  return e;
}

double CentrifugeConfig::reference_height() const {
  if (reference == "base") return 0.0;
  if (reference == "surface") return model_height;
  return model_height * (2.0 / 3.0);  // the effective radius (Taylor 1995): a third of the depth below the surface
}

std::vector<const ContactLaw*> MaterialConfig::wall_laws() const { return {&base, &front, &back}; }

double ExperimentConfig::critical_time_step() const {
  if (packing.particles) return packing.critical_time_step;
  if (material.shape.is_clump()) {  // as Simulation::critical_time_step for the smallest grain
    const ClumpTemplate grain = material.shape.clump->scaled_to(material.sizes.min_diameter());
    const double mass = contact_time_scale_mass(material.density * grain.volume,
                                                material.density * grain.principal_inertia, grain.bounding_radius());
    return trapdem::critical_time_step(material.particle, material.wall_laws(), mass, grain.smallest_radius());
  }
  const double r = 0.5 * material.sizes.min_diameter();
  const double m_min = material.density * 4.0 / 3.0 * std::numbers::pi * r * r * r;
  return trapdem::critical_time_step(material.particle, material.wall_laws(), m_min, r);
}

double ExperimentConfig::time_step() const {
  return numerics.time_step > 0.0 ? numerics.time_step : numerics.time_step_fraction * critical_time_step();
}

double ExperimentConfig::skin() const { return numerics.skin_fraction * material.sizes.max_diameter(); }

double ExperimentConfig::pour_skin() const {
  const double fraction = pluviation.skin_fraction > 0.0 ? pluviation.skin_fraction : numerics.skin_fraction;
  return fraction * material.sizes.max_diameter();
}

double ExperimentConfig::largest_skin() const { return packing.particles ? skin() : std::max(skin(), pour_skin()); }

std::int64_t ExperimentConfig::expected_particle_count() const {
  if (packing.particles) return std::int64_t(packing.particles->size());
  if (pluviation.count > 0) return pluviation.count;
  const double d = material.sizes.mean_diameter();
  const double volume = std::numbers::pi / 6.0 * d * d * d;
  return static_cast<std::int64_t>(pluviation.packing_fraction * box.width * box.depth * pluviation.fill_height / volume);
}

}  // namespace trapdem
