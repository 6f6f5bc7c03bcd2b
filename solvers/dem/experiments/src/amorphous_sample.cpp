#include "wearscale/dem/amorphous_sample.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/dem/cell_order.hpp"
#include "wearscale/dem/virial_stress.hpp"

namespace wearscale::dem {

namespace {
double ball_volume(double r) { return 4.0 / 3.0 * std::numbers::pi * r * r * r; }

void require(bool ok, const std::string& what, double value, const std::string& allowed) {
  if (!ok) throw InputError(fmt::format("amorphous DEM sample: {} = {}; allowed: {}", what, value, allowed));
}
}  // namespace

double volume_fraction(const Particles& p, const Box& box) {
  double v = 0.0;
  for (double r : p.radius) v += ball_volume(r);
  return v / box.volume();
}

Box periodic_box(const Vec3& size) {
  Box b;
  b.lo = {};
  b.hi = size;
  b.periodic = {true, true, true};
  return b;
}

namespace {
// Memory of a simulated particle, neighbour list and pair histories included:
// 154 MiB peak for 256 000 particles measured (bench/dem), about 630 B; with margin.
constexpr double bytes_per_particle = 1024.0;
}  // namespace

Particles insert_randomly(const AmorphousSpec& spec, double density) {
  for (int a = 0; a < 3; ++a)
    require(spec.box_size[a] > 0.0 && std::isfinite(spec.box_size[a]), fmt::format("box length along {}", "xyz"[a]),
            spec.box_size[a], "> 0");
  require(spec.volume_fraction > 0.0 && spec.volume_fraction < 1.0, "volume fraction", spec.volume_fraction,
          "0 < φ < 1");
  require(density > 0.0, "density", density, "> 0");
  require(spec.material >= 0 && spec.material < 256, "material tag", spec.material, "0 to 255");
  const DiameterSampler draw(spec.sizes);
  Random random(spec.seed);
  const Box box = periodic_box(spec.box_size);
  const double target = spec.volume_fraction * box.volume();
  // The count before anything is allocated (a box given in metres instead of d0 asks for 10^20 particles).
  const double estimate = target / ball_volume(0.5 * spec.sizes.mode) * 1.1 + 1.0;
  require_memory(estimate * bytes_per_particle,
                 fmt::format("a DEM sample of about {:.3g} particles (box {:g} × {:g} × {:g} m, d0 = {:g} m)", estimate,
                             spec.box_size[0], spec.box_size[1], spec.box_size[2], spec.sizes.mode),
                 "lengths are in metres unless given with a unit (\"60 nm\"); give a smaller box or larger particles");
  Particles p;
  p.reserve(static_cast<std::size_t>(estimate));
  double filled = 0.0;
  // Add the next particle while it brings the volume fraction closer to the
  // target: the result is within half a particle's volume of it.
  for (;;) {
    const double d = draw(random);
    const double v = ball_volume(0.5 * d);
    if (!(filled + 0.5 * v < target)) break;
    Sphere s;
    s.position = {random.uniform(box.lo.x, box.hi.x), random.uniform(box.lo.y, box.hi.y),
                  random.uniform(box.lo.z, box.hi.z)};
    s.radius = 0.5 * d;
    s.density = density;
    s.material = spec.material;
    s.body = spec.body;
    p.add(s);
    filled += v;
  }
  return p;
}

void match_density(Particles& p, const Box& box, double density) {
  require(density > 0.0, "density", density, "> 0");
  double mass = 0.0;
  for (double m : p.mass) mass += m;
  if (!(mass > 0.0)) return;
  const double factor = density * box.volume() / mass;
  for (std::size_t i = 0; i < p.size(); ++i) p.set_mass(i, factor * p.mass[i]);
}

RelaxationReport relax_amorphous(Simulation& sim, const RelaxationSettings& s) {
  auto* law = dynamic_cast<CohesiveLaw*>(&sim.law());
  if (!law) throw InputError("amorphous DEM sample: the relaxation (§6.2.2) needs the cohesive force law");
  require(s.time_step > 0.0, "time step / Δt_c", s.time_step, "> 0");
  require(s.repulsion_steps >= 0, "repulsion steps", static_cast<double>(s.repulsion_steps), "≥ 0");
  require(s.repulsion_damping >= 0.0, "repulsion damping / c_c", s.repulsion_damping, "≥ 0");
  require(s.cohesion_damping >= 0.0, "cohesion damping / c_c", s.cohesion_damping, "≥ 0");
  require(s.stress_tolerance > 0.0, "stress tolerance / E", s.stress_tolerance, "> 0");
  require(s.max_cohesion_steps >= 0, "maximum cohesion steps", static_cast<double>(s.max_cohesion_steps), "≥ 0");
  require(s.barostat_rate >= 0.0, "barostat rate", s.barostat_rate, "≥ 0");
  require(s.max_strain_per_step > 0.0, "maximum strain per step", s.max_strain_per_step, "> 0");

  RelaxationReport report;
  if (sim.particles().empty()) {
    report.converged = true;
    return report;
  }
  const bool cohesion = law->cohesion, tangential = law->tangential;
  for (const auto& m : law->materials()) report.modulus = std::max(report.modulus, m.young);
  const auto& p = sim.particles();
  const double dt = s.time_step * law->critical_time_step(p);  // 0.1 Δt_c (6.6)
  const double c_c = law->critical_damping(p);                 // (6.64)
  sim.set_time_step(dt);

  // A relaxation of 10⁵ particles or more takes minutes to tens of minutes
  // before the study proper starts: the log says so, and how it goes.
  const bool lengthy = p.size() >= 100000;
  if (lengthy)
    log::info("amorphous sample: relaxing {} particles (§6.2.2): {} steps of repulsion, then cohesion until every "
              "|σ_aa| < {:.3g} E (at most {} steps)",
              p.size(), s.repulsion_steps, s.stress_tolerance, s.max_cohesion_steps);
  // Phase 1: repulsion only, c = c_c, fixed periodic box.
  law->cohesion = false;
  law->tangential = false;
  sim.reset();
  sim.set_global_damping(s.repulsion_damping * c_c);
  sim.run(s.repulsion_steps);
  report.repulsion_steps = s.repulsion_steps;

  // Phase 2: cohesion, no tangential force, c = 0.02 c_c, the box rescaled
  // towards zero normal stress until |σ_aa| < tol E.
  law->cohesion = true;
  sim.reset();
  sim.set_global_damping(s.cohesion_damping * c_c);
  sim.set_track_virial(true);
  sim.compute_forces();
  const double limit = s.stress_tolerance * report.modulus;
  auto said = std::chrono::steady_clock::now();
  for (;;) {
    report.stress = box_stress(sim);
    if (lengthy && std::chrono::steady_clock::now() - said > std::chrono::minutes(1)) {
      said = std::chrono::steady_clock::now();
      log::info("amorphous sample: cohesion step {}, largest |σ_aa| = {:.3g} E (to reach {:.3g} E)", report.cohesion_steps,
                max_normal_stress(report.stress) / report.modulus, s.stress_tolerance);
    }
    if (max_normal_stress(report.stress) < limit) {
      report.converged = true;
      break;
    }
    if (report.cohesion_steps >= s.max_cohesion_steps) break;
    Box& box = sim.box();
    auto& x = sim.particles().position;
    for (int a = 0; a < 3; ++a) {
      if (!box.periodic[static_cast<std::size_t>(a)]) continue;
      const double strain = std::clamp(-s.barostat_rate * report.stress[static_cast<std::size_t>(a)] / report.modulus,
                                       -s.max_strain_per_step, s.max_strain_per_step);
      const double scale = 1.0 + strain;
      const double lo = box.lo[a];
      for (auto& xi : x) xi[a] = lo + scale * (xi[a] - lo);
      box.hi[a] = lo + scale * (box.hi[a] - lo);
    }
    if (interrupt_requested()) throw_if_interrupted("amorphous DEM sample (relaxation)");
    sim.step();
    ++report.cohesion_steps;
  }

  law->cohesion = cohesion;
  law->tangential = tangential;
  sim.reset();
  return report;
}

AmorphousSample make_amorphous_sample(const CohesiveMaterial& material, const AmorphousSpec& spec,
                                      const RelaxationSettings& settings) {
  require(settings.skin > 0.0, "skin / d0", settings.skin, "> 0");
  std::vector<CohesiveMaterial> table(static_cast<std::size_t>(spec.material) + 1, material);
  AmorphousSample out;
  Particles inserted = insert_randomly(spec, material.density);
  if (spec.numbered_along_cells) inserted.reorder(cell_order(inserted.position, 0.5 * spec.sizes.largest));
  const Box box = periodic_box(spec.box_size);
  out.inserted_volume_fraction = volume_fraction(inserted, box);
  Simulation sim(std::move(inserted), box, CohesiveLaw(std::move(table)),
                 NeighborSettings{settings.skin * spec.sizes.mode, 0, true});
  out.relaxation = relax_amorphous(sim, settings);
  out.box = sim.box();
  out.particles = std::move(sim.particles());
  auto& p = out.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int a = 0; a < 3; ++a) p.image[i][static_cast<std::size_t>(a)] -= out.box.wrap(a, p.position[i][a]);
    p.velocity[i] = {};
    p.omega[i] = {};
    p.force[i] = {};
    p.torque[i] = {};
  }
  out.relaxed_volume_fraction = volume_fraction(p, out.box);
  match_density(p, out.box, material.density);
  if (!spec.numbered_along_cells) {
    // The relaxed sample numbered along the cells (the same particles): the
    // random order of insertion makes the pairs of a large carved sample miss
    // the cache. The relaxation gives the same bits on any number of
    // threads, and so does this order.
    p.reorder(cell_order(p.position, 0.5 * spec.sizes.largest));
  }
  return out;
}

AmorphousSample make_carving_sample(const CohesiveMaterial& material, double d0, double largest, const Vec3& box_size,
                                    std::uint64_t seed, double stress_tolerance, long max_cohesion_steps,
                                    bool numbered_along_cells) {
  AmorphousSpec sample;
  sample.numbered_along_cells = numbered_along_cells;
  sample.sizes.mode = d0;
  sample.sizes.smallest = 0.75 * d0;
  sample.sizes.largest = largest > 0.0 ? largest : 1.25 * d0;
  sample.box_size = box_size;
  sample.seed = seed;
  RelaxationSettings relax;
  relax.stress_tolerance = stress_tolerance;
  relax.max_cohesion_steps = max_cohesion_steps;
  return make_amorphous_sample(material, sample, relax);
}

}  // namespace wearscale::dem
