#include "wearscale/dem/rough_shear.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/bonds.hpp"
#include "wearscale/dem/clusters.hpp"
#include "wearscale/dem/rigid_fit.hpp"
#include "wearscale/dem/rough_profile.hpp"
#include "wearscale/dem/steady_sliding.hpp"

namespace wearscale::dem {

namespace {

constexpr std::size_t smallest_wear_particle = 5;

void check(const RoughShearSpec& s) {
  check(s.cell, "rough shear");
  auto refuse = [](const char* what, double v, const char* allowed) {
    throw InputError(fmt::format("rough shear: {} = {}; allowed: {}", what, v, allowed));
  };
  if (!(s.roughness >= 0.0 && s.roughness <= 0.1)) refuse("roughness Sa/L", s.roughness, "0 ≤ Sa/L ≤ 0.1");
  if (!(s.hurst > 0.0 && s.hurst <= 1.0)) refuse("Hurst exponent", s.hurst, "0 < H ≤ 1");
  if (!(s.shortest_wavelength >= 2.0)) refuse("shortest wavelength (in d0)", s.shortest_wavelength, "≥ 2");
}

// The worn particles bonded only to worn particles (not the layer of worn
// particles still lining a surface), bonded to each other: the largest such
// cluster is the candidate wear particle (its core, without the shell that
// touches the surfaces).
std::vector<std::size_t> largest_worn_cluster(const SlidingCell& cell) {
  const auto& sim = cell.engine();
  auto worn = cell.worn_flags();
  const BondCriterion& bond = cell.bond();
  std::vector<char> lining(worn.size(), 0);
  for (const auto& [i, j] : bonded_pairs(sim.particles(), sim.box(), bond)) {
    if (worn[i] != 0.0 && worn[j] == 0.0) lining[i] = 1;
    if (worn[j] != 0.0 && worn[i] == 0.0) lining[j] = 1;
  }
  for (std::size_t i = 0; i < worn.size(); ++i)
    if (lining[i]) worn[i] = 0.0;
  BondCriterion among_worn;
  among_worn.max_gap = bond.max_gap;
  among_worn.gap = [&](const Particles& p, std::size_t i, std::size_t j) {
    if (worn[i] == 0.0 || worn[j] == 0.0) return -std::numeric_limits<double>::max();
    return bond.gap ? bond.gap(p, i, j) : bond.max_gap;
  };
  const auto analysis = find_clusters(sim.particles(), sim.box(), among_worn);
  for (const auto& c : analysis.clusters) {  // largest first
    if (c.size() < smallest_wear_particle) break;
    if (std::all_of(c.members.begin(), c.members.end(), [&](std::size_t i) { return worn[i] != 0.0; })) return c.members;
  }
  return {};
}

}  // namespace

RoughShearResult run_rough_shear(const RoughShearSpec& spec, const RoughShearObserver& observe,
                                 const RunCheckpoints& checkpoints) {
  check(spec);
  return run_rough_shear(spec, make_cell_sample(spec.cell), observe, checkpoints);
}

RoughShearResult run_rough_shear(const RoughShearSpec& spec, const AmorphousSample& sample,
                                 const RoughShearObserver& observe, const RunCheckpoints& checkpoints) {
  check(spec);
  const double d0 = spec.cell.d0;
  RoughShearResult out;
  out.d_star = critical_junction_size(spec.cell.material);
  out.relaxation_steps = sample.relaxation.repulsion_steps + sample.relaxation.cohesion_steps;

  // Two independent self-affine profiles over the relaxed length, the top one
  // lowered until it touches the bottom one at a single summit.
  Particles particles = sample.particles;
  const Box box = sample.box;
  const Vec3 size = box.length();
  RoughProfileSpec ps;
  ps.length = size.x;
  ps.sa = spec.roughness * size.x;
  ps.hurst = spec.hurst;
  ps.k_max = std::max(1, static_cast<int>(std::floor(size.x / (spec.shortest_wavelength * d0))));
  ps.seed = 2 * spec.cell.seed + 1;
  const RoughProfile bottom_profile(ps);
  ps.seed = 2 * spec.cell.seed + 2;
  const RoughProfile top_profile(ps);
  out.imposed_roughness = ps.sa;
  // The mean planes are `touch` apart, centred on the middle of the box.
  double touch = -std::numeric_limits<double>::max(), highest = 0.0;
  for (int k = 0; k < 4096; ++k) {
    const double x = size.x * k / 4096.0;
    touch = std::max(touch, bottom_profile(x) - top_profile(x));
  }
  for (int k = 0; k < 4096; ++k) {
    const double x = size.x * k / 4096.0;
    highest = std::max({highest, std::abs(bottom_profile(x) - 0.5 * touch), std::abs(top_profile(x) + 0.5 * touch)});
  }
  const double z_mid = box.lo.z + 0.5 * size.z;
  const double needed = 2.0 * (highest + (spec.cell.wall_thickness + 2.0) * d0);
  if (size.z < needed)
    throw InputError(fmt::format("rough shear: cell height H = {:.3g} m leaves less than two particles between the "
                                 "walls ({} d0) and the rough surfaces (|h| up to {:.3g} m); allowed: H ≥ {:.3g} m",
                                 size.z, spec.cell.wall_thickness, highest, needed));
  auto z_bottom = [&](double x) { return z_mid - 0.5 * touch + bottom_profile(x - box.lo.x); };
  auto z_top = [&](double x) { return z_mid + 0.5 * touch + top_profile(x - box.lo.x); };
  particles.remove_if([&](std::size_t i) {
    const Vec3& x = particles.position[i];
    return x.z > z_bottom(x.x) && x.z < z_top(x.x);
  });
  for (std::size_t i = 0; i < particles.size(); ++i)
    particles.body[i] = particles.position[i].z <= z_bottom(particles.position[i].x) ? cell_bottom : cell_top;

  SlidingCell cell(std::move(particles), box, spec.cell);
  out.particles = cell.engine().particles().size();
  out.time_step = cell.time_step();
  out.area = cell.area();
  const long planned = cell.planned_steps();
  const long every = spec.cell.record_every;
  const long window_start = planned - std::max((planned - cell.settle_steps()) / 5, every);
  std::vector<std::size_t> wear_particle;
  std::vector<Vec3> window_positions;
  bool window_open = false;
  long done = 0;
  // The run's state: the DEM system and the measurements so far.
  auto save = [&] {
    CheckpointState st;
    cell.engine().save_state(st);
    put_samples(st, "rough_shear.history", out.history);
    put_indices(st, "rough_shear.wear_particle", wear_particle);
    put_points(st, "rough_shear.window_positions", window_positions);
    st.put("rough_shear.tallies", std::vector<double>{double(done), out.peak_tangential_force, window_open ? 1.0 : 0.0});
    return st;
  };
  if (checkpoints.from != nullptr) {
    const CheckpointState& st = *checkpoints.from;
    cell.engine().restore_state(st);
    const auto& t = tallies(st, "rough_shear.tallies", 3);
    done = step_tally(st, "rough_shear.tallies", t[0]);
    out.peak_tangential_force = t[1];
    window_open = t[2] != 0.0;
    out.history = samples<SlidingSample>(st, "rough_shear.history");
    wear_particle = indices(st, "rough_shear.wear_particle");
    window_positions = points(st, "rough_shear.window_positions");
    if (window_positions.size() != wear_particle.size())
      throw InputError(fmt::format("{}: not the state of this rough-shear run", st.origin));
  } else {
    out.history.push_back(cell.advance(0));
  }
  cell.run([&](const SlidingSample& s, long step, long) {
    done = step;
    out.history.push_back(s);
    out.peak_tangential_force = std::max(out.peak_tangential_force, s.tangential_force);
    if (step >= window_start && !window_open && step < planned) {
      wear_particle = largest_worn_cluster(cell);
      window_positions = unwrapped_positions(cell.engine(), wear_particle);
      window_open = true;
    }
    if (observe) observe(cell, s, step, planned);
    if (step < planned) checkpoints.offer(step, save);
  }, done);
  out.steps = planned;

  const SteadySliding steady = steady_sliding(out.history);
  if (steady.samples > 0) {
    out.mean_tangential_force = steady.tangential_force;
    out.mean_pressure = steady.normal_force / out.area;
    out.friction = steady.friction;
  }
  const auto worn = cell.worn_flags();
  for (double w : worn) out.worn += w != 0.0 ? 1u : 0u;
  out.worn_fraction = static_cast<double>(out.worn) / static_cast<double>(cell.engine().particles().count_mobile());
  out.wear_particle = wear_particle.size();
  if (!wear_particle.empty()) {
    out.wear_particle_residual = rigid_fit(window_positions, unwrapped_positions(cell.engine(), wear_particle)).residual;
    out.regime = out.wear_particle_residual < 1.0 / 3.0 ? "rolling wear particles" : "shear band";
  } else {
    out.regime = out.worn < smallest_wear_particle ? "no wear particle" : "shear band";
  }
  return out;
}

}  // namespace wearscale::dem
