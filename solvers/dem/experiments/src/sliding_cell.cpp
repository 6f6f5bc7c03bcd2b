#include "wearscale/dem/sliding_cell.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/shapes.hpp"
#include "wearscale/dem/surface_roughness.hpp"

namespace wearscale::dem {

void check(const SlidingCellSpec& s, const char* study) {
  require_modelled(s.material);
  auto refuse = [&](const char* what, double v, const std::string& allowed) {
    throw InputError(fmt::format("{}: {} = {}; allowed: {}", study, what, v, allowed));
  };
  auto positive = [&](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) refuse(what, v, "> 0");
  };
  positive(s.d0, "d0");
  positive(s.velocity, "velocity");
  positive(s.time_step, "time step (in Δt_c)");
  if (!(s.time_step < 1.0)) refuse("time step (in Δt_c)", s.time_step, "(0, 1): the cohesive law's stable step (6.6)");
  if (!(s.velocity < 1000.0)) refuse("velocity", s.velocity, "(0, 1000) m/s");
  positive(s.sliding_distance, "sliding distance");
  positive(s.box.x, "cell length L");
  positive(s.box.y, "cell depth W");
  positive(s.box.z, "cell height H");
  if (!(s.settle_distance >= 0.0) || !std::isfinite(s.settle_distance)) refuse("settle distance", s.settle_distance, "≥ 0");
  if (!(s.pressure >= 0.0 && s.pressure <= s.material.tensile_strength))
    refuse("pressure", s.pressure, fmt::format("0 ≤ p ≤ σ_m,N = {:g} (the material's normal strength)",
                                               s.material.tensile_strength));
  if (!(s.wall_thickness >= 1.0 && s.wall_thickness <= 10.0)) refuse("wall thickness (in d0)", s.wall_thickness, "1 … 10");
  if (!(s.relax_tolerance > 0.0 && s.relax_tolerance < 1e-2))
    refuse("relaxation tolerance", s.relax_tolerance, "(0, 0.01)");
  if (s.largest != 0.0 && !(s.largest >= s.d0)) refuse("largest diameter d_l", s.largest, fmt::format("≥ d0 = {}", s.d0));
  if (!(s.wall_damping >= 0.0 && s.wall_damping <= 1.0)) refuse("wall damping (of critical)", s.wall_damping, "0 ≤ ζ ≤ 1");
  if (s.record_every < 1) refuse("record_every", static_cast<double>(s.record_every), "≥ 1");
  // The neighbour list needs periodic lengths of at least twice its cutoff.
  const double d_l = s.largest > 0.0 ? s.largest : 1.25 * s.d0;
  if (s.box.y < d_l) refuse("cell depth W", s.box.y, fmt::format("≥ d_l = {:.3g} m (the largest particle)", d_l));
  if (s.box.x < 10.0 * s.d0) refuse("cell length L", s.box.x, fmt::format("≥ 10 d0 = {:.3g} m", 10.0 * s.d0));
}

AmorphousSample make_cell_sample(const SlidingCellSpec& spec) {
  return make_carving_sample(spec.material, spec.d0, spec.largest, spec.box, spec.seed, spec.relax_tolerance,
                             spec.max_relax_steps);
}

SlidingCell::SlidingCell(Particles particles, Box box, const SlidingCellSpec& spec) : spec_(spec) {
  for (std::size_t i = 0; i < particles.size(); ++i) {
    particles.velocity[i] = {};
    particles.omega[i] = {};
  }
  box.periodic = {true, true, false};
  const Vec3 size = box.length();
  const auto [z_min, z_max] = extent(particles, 2);
  const double wall = spec.wall_thickness * spec.d0;
  auto bottom = indices_inside(particles, below(2, z_min + wall));
  auto top = indices_inside(particles, above(2, z_max - wall));
  if (bottom.empty() || top.empty())
    throw InputError(fmt::format("sliding cell: no particle for a wall of {} d0; allowed: a cell several d0 high",
                                 spec.wall_thickness));
  double wall_mass = 0.0, max_radius = 0.0;
  for (std::size_t i : top) wall_mass += particles.mass[i];
  for (double r : particles.radius) max_radius = std::max(max_radius, r);

  auto law = make_contact_law(spec.law, {{spec.material}, spec.d0, spec.friction});
  const double dt = spec.time_step * law->critical_time_step(particles);
  bond_ = BondCriterion::cohesive(CohesiveLaw({spec.material}), max_radius);
  engine_ = make_engine(spec.engine, {std::move(particles), box, std::move(law),
                                      NeighborSettings{0.1 * spec.d0, 0, true, spec.history_of_touching_pairs_only}});
  engine_->set_time_step(dt);
  area_ = size.x * size.y;
  settle_ = dem::planned_steps(spec.settle_distance / (spec.velocity * dt), "the sliding cell's settling");
  slide_ = dem::planned_steps(spec.sliding_distance / (spec.velocity * dt), "the sliding cell's slide");
  // The pressed wall's normal motion is damped (a fraction of critical on the
  // stiffness E A0 / H of the cell) to calm its ringing; the particles have
  // no global damping.
  const double stiffness = spec.material.young * area_ / (z_max - z_min);
  auto pressed = WallMotion::pressed(2, spec.pressure, area_, +1, {settle_ > 0 ? 0.0 : spec.velocity, 0.0, 0.0});
  pressed.damping = spec.wall_damping * 2.0 * std::sqrt(stiffness * wall_mass);
  bottom_wall_ = engine_->add_wall(std::move(bottom), WallMotion::fixed());
  top_wall_ = engine_->add_wall(std::move(top), pressed);
  tags_ = std::make_unique<WornParticles>(engine_->particles(), engine_->box(), bond_);
}

std::vector<double> SlidingCell::worn_flags() const {
  const auto& p = engine_->particles();
  const auto worn = tags_->worn(p, engine_->box());
  std::vector<double> flag(p.size(), 0.0);
  for (std::size_t i = 0; i < p.size(); ++i) flag[i] = worn[i] && !p.frozen(i) ? 1.0 : 0.0;
  return flag;
}

SlidingSample SlidingCell::advance(long steps) {
  // p_T and p_N from both walls: their mean cancels the inertia of the
  // sample between them.
  double sum_t = 0.0, sum_n = 0.0;
  long summed = 0;
  engine_->run(steps, [&](long) {
    sum_t += 0.5 * (engine_->wall(bottom_wall_).force.x - engine_->wall(top_wall_).force.x);
    sum_n += 0.5 * (engine_->wall(top_wall_).force.z - engine_->wall(bottom_wall_).force.z);
    ++summed;
  }, Engine::StopInside::Yes);
  SlidingSample s;
  s.time = engine_->time();
  s.sliding = engine_->wall(top_wall_).displacement.x;
  s.tangential_force = summed > 0 ? sum_t / static_cast<double>(summed) : 0.0;
  s.normal_force = summed > 0 ? sum_n / static_cast<double>(summed) : 0.0;
  s.kinetic_energy = engine_->kinetic_energy();
  const auto worn = worn_flags();
  const auto& p = engine_->particles();
  for (double w : worn) s.worn += w;
  auto surface_of = [&](int body) {
    return [&, body](std::size_t i) { return p.body[i] == body && worn[i] == 0.0; };
  };
  s.roughness_bottom = surface_roughness(p, engine_->box(), surface_of(cell_bottom), Facing::up, spec_.d0);
  s.roughness_top = surface_roughness(p, engine_->box(), surface_of(cell_top), Facing::down, spec_.d0);
  return s;
}

void SlidingCell::run(const std::function<void(const SlidingSample&, long step, long planned)>& each, long from) {
  const long planned = planned_steps();
  for (long step = from; step < planned;) {
    const long chunk = std::min(spec_.record_every, step < settle_ ? settle_ - step : planned - step);
    const auto s = advance(chunk);
    step += chunk;
    if (step == settle_) engine_->set_wall_velocity(top_wall_, 0, spec_.velocity);  // start sliding
    each(s, step, planned);
  }
}

}  // namespace wearscale::dem
