#include "wearscale/dem/sheared_junction.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <set>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/amorphous_sample.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/bonds.hpp"
#include "wearscale/dem/clusters.hpp"
#include "wearscale/dem/rigid_fit.hpp"
#include "wearscale/dem/shapes.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

namespace {

constexpr int bottom_body = 0, junction_body = 1, top_body = 2;

void check(const ShearedJunctionSpec& s) {
  require_modelled(s.material);
  auto positive = [](double v, const char* what, const char* allowed) {
    if (!(v > 0.0) || !std::isfinite(v))
      throw InputError(fmt::format("sheared junction: {} = {}; allowed: {}", what, v, allowed));
  };
  positive(s.d0, "d0", "> 0");
  positive(s.diameter, "junction diameter D", "> 0");
  positive(s.velocity, "velocity", "> 0");
  positive(s.time_step, "time step", "> 0 (in Δt_c)");
  if (!(s.time_step < 1.0))
    throw InputError(fmt::format("sheared junction: time step = {:g} Δt_c; allowed: (0, 1) (the cohesive law's stable "
                                 "step, 6.6)",
                                 s.time_step));
  if (!(s.sliding_distance >= 0.0 && std::isfinite(s.sliding_distance)))
    throw InputError(fmt::format("sheared junction: sliding distance = {:g}; allowed: ≥ 0 (0: 1.5 D)", s.sliding_distance));
  if (s.record_every < 1)
    throw InputError(fmt::format("sheared junction: record_every = {}; allowed: ≥ 1", s.record_every));
  // Beyond the normal strength σ_m,N the cohesive model holds no solid to shear (as the sliding cell's bound).
  if (!(s.pressure >= 0.0 && s.pressure <= s.material.tensile_strength))
    throw InputError(fmt::format("sheared junction: pressure = {:g}; allowed: 0 ≤ p ≤ σ_m,N = {:g} (the material's "
                                 "normal strength)",
                                 s.pressure, s.material.tensile_strength));
  const double height = s.height_ratio * s.diameter;
  if (s.diameter > 0.5 * s.box.x)
    throw InputError(fmt::format("sheared junction: D = {:.3g} m is more than half the sliding length {:.3g} m of the box; allowed: D ≤ {:.3g}",
                                 s.diameter, s.box.x, 0.5 * s.box.x));
  const double solid = 0.5 * (s.box.z - height);
  if (solid < (s.wall_thickness + 1.0) * s.d0)
    throw InputError(fmt::format(
        "sheared junction: each surface is {:.3g} m thick, less than its wall ({} d0) plus one particle; "
        "allowed: box height ≥ H + 2 ({} + 1) d0 = {:.3g} m",
        solid, s.wall_thickness, s.wall_thickness, height + 2.0 * (s.wall_thickness + 1.0) * s.d0));
}

}  // namespace

ShearedJunctionResult run_sheared_junction(const ShearedJunctionSpec& spec, const JunctionObserver& observe,
                                           const RunCheckpoints& checkpoints) {
  check(spec);
  ShearedJunctionResult out;
  const auto& m = spec.material;
  out.d_star = critical_junction_size(m);

  // The relaxed amorphous box (§6.2.2), then carved (§6.3).
  auto made = make_carving_sample(m, spec.d0, spec.largest, spec.box, spec.seed, spec.relax_tolerance,
                                  spec.max_relax_steps);
  out.relaxation_steps = made.relaxation.repulsion_steps + made.relaxation.cohesion_steps;
  Particles particles = std::move(made.particles);
  Box box = made.box;
  const Vec3 size = box.length();
  const double height = spec.height_ratio * spec.diameter;
  const double z_gap_lo = box.lo.z + 0.5 * (size.z - height), z_gap_hi = z_gap_lo + height;
  // The junction: a cylinder of diameter D whose axis runs along y through the
  // middle of the gap, across the periodic depth of the box (quasi-2D, as the
  // MD junctions of Aghababaei et al. 2016 behind (6.65)); inside the gap of
  // height D/2 it is a barrel welded to both surfaces.
  const Vec3 axis_mid{box.lo.x + 0.5 * size.x, 0.0, z_gap_lo + 0.5 * height};
  const double radius = 0.5 * spec.diameter;
  // The two surfaces are the particles entirely below or above the gap of
  // height H; of the particles reaching into the gap, those centred within the
  // cylinder make the junction, the others are removed.
  auto in_gap = [&](std::size_t i) {
    const double z = particles.position[i].z, r = particles.radius[i];
    return z + r > z_gap_lo && z - r < z_gap_hi;
  };
  auto in_column = [&](std::size_t i) {
    const Vec3 d = particles.position[i] - axis_mid;
    return d.x * d.x + d.z * d.z <= radius * radius;
  };
  particles.remove_if([&](std::size_t i) { return in_gap(i) && !in_column(i); });
  for (std::size_t i = 0; i < particles.size(); ++i) {
    particles.body[i] = in_gap(i) ? junction_body : (particles.position[i].z < z_gap_lo ? bottom_body : top_body);
    particles.velocity[i] = {};
    particles.omega[i] = {};
  }
  box.periodic = {true, true, false};
  const auto [z_min, z_max] = extent(particles, 2);
  const double wall = spec.wall_thickness * spec.d0;
  auto bottom = indices_inside(particles, below(2, z_min + wall));
  auto top = indices_inside(particles, above(2, z_max - wall));

  CohesiveLaw law({m});
  const double dt = spec.time_step * law.critical_time_step(particles);
  double max_radius = 0.0;
  for (double r : particles.radius) max_radius = std::max(max_radius, r);
  const BondCriterion bonded = BondCriterion::cohesive(law, max_radius);
  const auto engine = make_engine(spec.engine, {std::move(particles), box, std::make_unique<CohesiveLaw>(std::move(law)),
                                                NeighborSettings{0.1 * spec.d0, 0, true}});
  Engine& sim = *engine;
  sim.set_time_step(dt);
  sim.add_wall(std::move(bottom), WallMotion::fixed());
  auto pressed = WallMotion::pressed(2, spec.pressure, size.x * size.y, +1, {spec.velocity, 0, 0});
  const int top_wall = sim.add_wall(std::move(top), pressed);
  out.time_step = dt;

  std::vector<std::size_t> junction_set;
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    if (sim.particles().body[i] == junction_body && sim.particles().wall[i] == no_wall) junction_set.push_back(i);
  out.particles = sim.particles().size();
  out.junction_particles = junction_set.size();
  if (junction_set.empty())
    throw InputError(fmt::format("sheared junction: no particle inside the junction of D = {:.3g} m with d0 = {:.3g} m; "
                                 "allowed: D several times d0",
                                 spec.diameter, spec.d0));

  const double distance = spec.sliding_distance > 0.0 ? spec.sliding_distance : 1.5 * spec.diameter;
  const long planned = planned_steps(distance / (spec.velocity * dt), "the sheared junction's slide");
  const long window_start = planned - std::max(planned / 5, spec.record_every);
  // The bonds of the carved sample: a junction that detaches breaks all of
  // its original bonds with the surfaces (§6.3), one that deforms
  // plastically stays welded to at least one of them.
  const auto original = bonded_pairs(sim.particles(), sim.box(), bonded);
  const std::set<std::pair<std::size_t, std::size_t>> original_set(original.begin(), original.end());
  std::vector<Vec3> window_positions;
  double window_sliding = 0.0;

  auto sample_now = [&] {
    JunctionSample s;
    s.time = sim.time();
    s.sliding = sim.wall(top_wall).displacement.x;
    s.tangential_force = -sim.wall(top_wall).force.x;
    s.normal_force = sim.wall(top_wall).force.z;  // the sample pushes the top wall up
    s.kinetic_energy = sim.kinetic_energy();
    return s;
  };
  long step = 0;
  // The run's state: the DEM system and the measurements so far.
  auto save = [&] {
    CheckpointState st;
    sim.save_state(st);
    put_samples(st, "junction.history", out.history);
    put_points(st, "junction.window_positions", window_positions);
    st.put("junction.tallies", std::vector<double>{double(step), out.peak_tangential_force, window_sliding});
    return st;
  };
  if (checkpoints.from != nullptr) {
    const CheckpointState& st = *checkpoints.from;
    sim.restore_state(st);
    const auto& t = tallies(st, "junction.tallies", 3);
    step = step_tally(st, "junction.tallies", t[0]);
    out.peak_tangential_force = t[1];
    window_sliding = t[2];
    out.history = samples<JunctionSample>(st, "junction.history");
    window_positions = points(st, "junction.window_positions");
  }
  while (step < planned) {
    const long chunk = std::min(spec.record_every, planned - step);
    sim.run(chunk);
    step += chunk;
    const auto s = sample_now();
    out.history.push_back(s);
    out.peak_tangential_force = std::max(out.peak_tangential_force, s.tangential_force);
    if (step >= window_start && window_positions.empty()) {
      window_positions = unwrapped_positions(sim, junction_set);
      window_sliding = s.sliding;
    }
    if (observe) observe(sim, s, step, planned);
    if (step < planned) checkpoints.offer(step, save);
  }
  out.steps = planned;
  const auto fit = rigid_fit(window_positions, unwrapped_positions(sim, junction_set));
  out.rigid_residual = fit.residual;
  // Rolling without slip between a fixed and a moving surface turns the
  // particle by (sliding distance)/D: rolling_rate ≈ 1.
  const double slid = sim.wall(top_wall).displacement.x - window_sliding;
  out.rolling_rate = slid > 0.0 ? fit.angle_y * spec.diameter / slid : 0.0;

  const auto current = bonded_pairs(sim.particles(), sim.box(), bonded);
  std::set<std::pair<std::size_t, std::size_t>> intact;
  for (const auto& pr : current)
    if (original_set.count(pr)) intact.insert(pr);
  BondCriterion still_bonded;
  still_bonded.max_gap = bonded.max_gap;
  still_bonded.gap = [&](const Particles& p, std::size_t i, std::size_t j) {
    const auto key = std::make_pair(std::min(i, j), std::max(i, j));
    return intact.count(key) ? (bonded.gap ? bonded.gap(p, i, j) : bonded.max_gap) : -1e300;
  };
  const auto analysis = find_clusters(sim.particles(), sim.box(), still_bonded);
  for (const auto& c : analysis.clusters) {
    if (c.touches_wall()) continue;
    std::size_t from_junction = 0;
    for (std::size_t i : c.members) from_junction += sim.particles().body[i] == junction_body ? 1u : 0u;
    if (from_junction > out.detached_cluster) {
      out.detached_cluster = from_junction;
      out.detached_diameter = c.equivalent_diameter;
    }
  }
  // A junction slid over resists: no resistance at all is no result (a crushed or torn-apart sample).
  if (!(out.peak_tangential_force > 0.0) || !std::isfinite(out.peak_tangential_force))
    throw NumericalError("dem sheared junction", out.steps, "peak tangential force",
                         fmt::format("{:g}: the top wall met no resistance while sliding over the junction (the "
                                     "sample did not hold together)",
                                     out.peak_tangential_force));
  // The verdict: the junction turned into a rolling particle when its
  // particles moved as one rigid body (misfit under a third of the motion)
  // that rolled (at least half the rotation of rolling without slip).
  out.detached = out.rigid_residual < 1.0 / 3.0 && out.rolling_rate > 0.5;
  return out;
}

}  // namespace wearscale::dem
