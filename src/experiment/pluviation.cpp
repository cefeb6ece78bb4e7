#include "experiment/pluviation.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <random>

#include <fmt/format.h>

#include "core/errors.hpp"

namespace trapdem {

Hopper::Hopper(const ExperimentConfig& c) : config_(&c) {
  const double g = ExperimentConfig::standard_gravity;
  entry_speed_ = std::sqrt(2.0 * g * c.pluviation.drop_height);
  // Room for the largest grain in any orientation (a clump's bounding sphere).
  spacing_ = 1.1 * c.material.sizes.max_diameter() * c.material.shape.bounding_ratio();
  // The time for a layer to fall one spacing: s = v t + g t^2 / 2.
  interval_ = (-entry_speed_ + std::sqrt(entry_speed_ * entry_speed_ + 2.0 * g * spacing_)) / g;
}

double Hopper::surface_height() const {
  const ExperimentConfig& c = *config_;
  return inserted_mass_ / (c.material.density * c.pluviation.packing_fraction * c.box.width * c.box.depth);
}

int Hopper::sites_along(int axis) const {
  const BoxConfig& box = config_->box;
  if (axis == 1 && box.periodic_depth) return std::max(1, int(box.depth / spacing_));
  return std::max(1, int(((axis == 0 ? box.width : box.depth) - spacing_) / spacing_) + 1);
}

double Hopper::planned_duration(std::int64_t count) const {
  const ExperimentConfig& c = *config_;
  const double layers = std::ceil(double(count) / double(sites_along(0) * sites_along(1)));
  double seconds = layers * interval_;
  if (c.pluviation.flow_rate > 0.0) {
    const double d = c.material.sizes.mean_diameter();
    seconds = std::max(seconds, double(count) * c.material.density * std::numbers::pi / 6.0 * d * d * d /
                                    c.pluviation.flow_rate);
  }
  return seconds;
}

bool Hopper::finished(const Simulation&) const {
  const PluviationConfig& p = config_->pluviation;
  if (box_full_) return true;
  if (p.count > 0 && inserted_ >= p.count) return true;
  return p.fill_height > 0.0 && surface_height() >= p.fill_height;
}

std::size_t Hopper::pour(Simulation& sim, Decomposition* ranks) {
  const ExperimentConfig& c = *config_;
  if (sim.time() < next_time_ || finished(sim)) return 0;
  const double elapsed = interval_;
  next_time_ = sim.time() + interval_;

  // The band sits two diameters above the highest particle that is not falling in the stream
  // (on ranks: the highest over every rank's own particles; a maximum does not depend on the order).
  const Particles& p = sim.particles();
  const std::size_t owned = sim.owned_count();
  double top = 0.0;
  for (std::size_t i = 0; i < owned; ++i)
    if (p.velocity[i].z > -0.5 * entry_speed_ || entry_speed_ == 0.0) top = std::max(top, p.position[i].z + p.radius[i]);
  if (ranks) top = ranks->max(top);
  const double ceiling = band_ceiling();
  const bool at_ceiling = top + 2.0 * c.material.sizes.max_diameter() >= ceiling;
  const double z = std::min(top + 2.0 * c.material.sizes.max_diameter(), ceiling);

  // Sites on a grid across the box; a fresh generator per insertion keeps the pour reproducible
  // from a checkpoint without storing generator state.
  std::seed_seq seed{std::uint64_t(c.pluviation.seed), std::uint64_t(event_)};
  std::mt19937_64 rng(seed);
  const double margin = 0.5 * spacing_;
  const int nx = sites_along(0), ny = sites_along(1);
  std::vector<int> sites(std::size_t(nx) * ny);
  for (std::size_t k = 0; k < sites.size(); ++k) sites[k] = int(k);
  std::shuffle(sites.begin(), sites.end(), rng);

  // Particles already near the band (bouncing back up from the deposit, or the last layer not yet
  // clear): a site that would overlap one of them is skipped in this insertion. Each rank looks at
  // its own particles; a site is free when it is free on every rank.
  const double d_max = c.material.sizes.max_diameter() * c.material.shape.bounding_ratio();
  std::vector<std::size_t> nearby;
  for (std::size_t i = 0; i < owned; ++i)
    if (std::fabs(p.position[i].z - z) < 2.0 * d_max) nearby.push_back(i);
  auto blocked = [&](const Vec3& x, double r) {
    for (std::size_t i : nearby) {
      Vec3 d = x - p.position[i];
      if (c.box.periodic_depth) d = sim.settings().domain.minimum_image(d);
      const double reach = r + p.radius[i] + 0.05 * d_max;
      if (norm2(d) < reach * reach) return 1.0;
    }
    return 0.0;
  };

  // Each site's draws (size, then the three jitters) in the order of the sites, whatever is
  // inserted: the stream, and so the sizes and sites, are the same on any rank count. The sites
  // are looked at in chunks (one reduction per chunk on ranks), as far as the pour goes.
  const double density = c.material.density;
  if (c.pluviation.flow_rate > 0.0) mass_budget_ += c.pluviation.flow_rate * elapsed;
  std::uniform_real_distribution<double> jitter(-0.04, 0.04);
  constexpr std::size_t kChunk = 256;
  std::vector<double> diameter, site_blocked;
  std::vector<Vec3> site_x;
  std::vector<Quaternion> site_q;  // clumps: each site's orientation, drawn uniformly
  const ParticleShape& shape = c.material.shape;
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::size_t count = 0;
  bool stop = false;  // the count, the fill height or the flow's budget says: no more now
  for (std::size_t first = 0; first < sites.size() && !stop; first += kChunk) {
    const std::size_t last = std::min(sites.size(), first + kChunk);
    diameter.clear();
    site_x.clear();
    site_blocked.clear();
    site_q.clear();
    for (std::size_t k = first; k < last; ++k) {
      const double d = c.material.sizes.sample(rng);
      const int ix = sites[k] % nx, iy = sites[k] / nx;
      const double y0 = c.box.periodic_depth ? 0.5 * spacing_ : margin;
      const Vec3 x{margin + ix * spacing_ + jitter(rng) * spacing_, y0 + iy * spacing_ + jitter(rng) * spacing_,
                   z + jitter(rng) * spacing_};
      diameter.push_back(d);
      site_x.push_back(x);
      site_blocked.push_back(blocked(x, 0.5 * d * shape.bounding_ratio()));
      if (shape.is_clump()) {
        const double u1 = unit(rng), u2 = unit(rng), u3 = unit(rng);
        site_q.push_back(uniform_orientation(u1, u2, u3));
      }
    }
    if (ranks) ranks->max(site_blocked.data(), int(site_blocked.size()));
    for (std::size_t k = 0; k < diameter.size(); ++k) {
      stop = (c.pluviation.count > 0 && inserted_ >= c.pluviation.count) ||
             (c.pluviation.fill_height > 0.0 && surface_height() >= c.pluviation.fill_height);
      if (stop) break;
      const double d = diameter[k];
      const double mass = density * std::numbers::pi / 6.0 * d * d * d;
      stop = c.pluviation.flow_rate > 0.0 && mass_budget_ < mass;
      if (stop) break;
      if (site_blocked[k] > 0.0) continue;
      const std::int64_t id = inserted_ + 1;
      const Vec3 fall{0.0, 0.0, -entry_speed_};
      if (shape.is_clump()) {  // one process only (TrapdoorExperiment::attach_decomposition)
        const ClumpTemplate grain = shape.clump->scaled_to(d);
        sim.add_body(id, next_member_id_, grain, density, site_x[k], site_q[k], fall);
        next_member_id_ += std::int64_t(grain.members.size());
      } else if (sim.owns_site(site_x[k])) {
        sim.add_particle(id, site_x[k], 0.5 * d, density, fall);
      }
      if (c.pluviation.flow_rate > 0.0) mass_budget_ -= mass;
      inserted_mass_ += mass;
      ++inserted_;
      ++count;
    }
  }
  // Sites ran out before the budget: the band cannot pass the flow rate asked for.
  if (c.pluviation.flow_rate > 0.0 && count == sites.size() && mass_budget_ > 0.0) {
    band_limited_ = true;
    mass_budget_ = 0.0;
  }
  // The box is full: the band cannot rise above its ceiling, the deposit has reached it and nearly
  // every site is taken, insertion after insertion, while particles are still due (a looser
  // material needs more height for the same count: 300 000 beads of RF2 stand higher than the
  // 360 mm box). Pouring on would push particles into the heap at the band, not rain them; the
  // pour ends as a model is filled to its rim, with fewer particles than the count.
  const bool starved = !stop && count * kStarvedSiteFraction < sites.size();
  stalled_insertions_ = at_ceiling && starved ? stalled_insertions_ + 1 : 0;
  if (stalled_insertions_ >= kStalledInsertionsWhenFull) box_full_ = true;
  ++event_;
  return count;
}

double Hopper::band_ceiling() const {
  return config_->box.height + 3.0 * config_->material.sizes.max_diameter();
}

std::map<std::string, std::string> Hopper::state() const {
  auto hex = [](double v) { return fmt::to_string(std::bit_cast<std::uint64_t>(v)); };
  return {{"hopper.next_time", hex(next_time_)},
          {"hopper.mass_budget", hex(mass_budget_)},
          {"hopper.inserted_mass", hex(inserted_mass_)},
          {"hopper.event", fmt::to_string(event_)},
          {"hopper.inserted", fmt::to_string(inserted_)},
          {"hopper.next_member_id", fmt::to_string(next_member_id_)},
          {"hopper.band_limited", band_limited_ ? "1" : "0"},
          {"hopper.stalled_insertions", fmt::to_string(stalled_insertions_)},
          {"hopper.box_full", box_full_ ? "1" : "0"}};
}

void Hopper::restore(const std::map<std::string, std::string>& s) {
  auto get = [&](const char* key) -> const std::string& {
    auto it = s.find(key);
    if (it == s.end()) throw InputError(std::string("checkpoint: missing hopper state '") + key + "'");
    return it->second;
  };
  auto dbl = [&](const char* key) { return std::bit_cast<double>(std::stoull(get(key))); };
  next_time_ = dbl("hopper.next_time");
  mass_budget_ = dbl("hopper.mass_budget");
  inserted_mass_ = dbl("hopper.inserted_mass");
  event_ = std::stoll(get("hopper.event"));
  inserted_ = std::stoll(get("hopper.inserted"));
  // Absent from a checkpoint written before clumps: spheres, no member ids.
  const auto member = s.find("hopper.next_member_id");
  next_member_id_ = member == s.end() ? 1 : std::stoll(member->second);
  band_limited_ = get("hopper.band_limited") == "1";
  // Absent from a checkpoint written before the box-full rule: no stall counted yet, not full.
  const auto stalled = s.find("hopper.stalled_insertions"), full = s.find("hopper.box_full");
  stalled_insertions_ = stalled == s.end() ? 0 : std::stoll(stalled->second);
  box_full_ = full != s.end() && full->second == "1";
}

}  // namespace trapdem
