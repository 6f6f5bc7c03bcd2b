#include "wearscale/dem/trapped_particles.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <numbers>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/rigid_fit.hpp"
#include "wearscale/dem/steady_sliding.hpp"

namespace wearscale::dem {

namespace {

void check(const TrappedParticlesSpec& s) {
  check(s.cell, "trapped particles");
  auto refuse = [](const char* what, double v, const std::string& allowed) {
    throw InputError(fmt::format("trapped particles: {} = {}; allowed: {}", what, v, allowed));
  };
  if (!(s.fit_from >= 0.0 && s.fit_from < 1.0)) refuse("fit_from (fraction of the slide)", s.fit_from, "0 ≤ f < 1");
  if (s.count < 1 || s.count > 16) refuse("particle count n", s.count, "1 ≤ n ≤ 16");
  if (!(s.diameter >= 3.0 * s.cell.d0) || !std::isfinite(s.diameter))
    refuse("particle diameter D", s.diameter, fmt::format("≥ 3 d0 = {:.3g} m", 3.0 * s.cell.d0));
  if (!(s.clearance >= 0.0 && s.clearance < 1.0)) refuse("clearance (in d0)", s.clearance, "0 ≤ c < 1");
  if (s.cell.box.x < s.count * (s.diameter + s.cell.d0))
    refuse("cell length L", s.cell.box.x,
           fmt::format("≥ n (D + d0) = {:.3g} m, room for the particles side by side", s.count * (s.diameter + s.cell.d0)));
  const double needed = s.diameter + 2.0 * (s.cell.wall_thickness + 2.0) * s.cell.d0;
  if (s.cell.box.z < needed)
    refuse("cell height H", s.cell.box.z,
           fmt::format("≥ D + 2 ({} + 2) d0 = {:.3g} m: each surface its wall and two particles", s.cell.wall_thickness, needed));
}

}  // namespace

TrappedParticlesResult run_trapped_particles(const TrappedParticlesSpec& spec, const TrappedParticlesObserver& observe,
                                             const RunCheckpoints& checkpoints) {
  check(spec);
  return run_trapped_particles(spec, make_cell_sample(spec.cell), observe, checkpoints);
}

TrappedParticlesResult run_trapped_particles(const TrappedParticlesSpec& spec, const AmorphousSample& sample,
                                             const TrappedParticlesObserver& observe,
                                             const RunCheckpoints& checkpoints) {
  check(spec);
  const double d0 = spec.cell.d0;
  TrappedParticlesResult out;
  out.d_star = critical_junction_size(spec.cell.material);
  out.relaxation_steps = sample.relaxation.repulsion_steps + sample.relaxation.cohesion_steps;

  // The gap of height D across the middle of the relaxed box: the surfaces
  // are the particles entirely outside it; inside it, the particles wholly
  // within one of the n discs (axes along y, evenly spaced along x) shrunk by
  // the clearance are loose particles, the others are removed.
  Particles particles = sample.particles;
  const Box box = sample.box;
  const Vec3 size = box.length();
  const double z_lo = box.lo.z + 0.5 * (size.z - spec.diameter), z_hi = z_lo + spec.diameter;
  const double z_axis = 0.5 * (z_lo + z_hi);
  const double reach = 0.5 * spec.diameter - spec.clearance * d0;
  const double spacing = size.x / spec.count;
  auto disc_of = [&](std::size_t i) {
    const Vec3& x = particles.position[i];
    const int k = std::clamp(static_cast<int>(std::floor((x.x - box.lo.x) / spacing)), 0, spec.count - 1);
    const double dx = x.x - (box.lo.x + (k + 0.5) * spacing), dz = x.z - z_axis;
    return std::hypot(dx, dz) + particles.radius[i] <= reach ? k : -1;
  };
  auto in_gap = [&](std::size_t i) {
    const double z = particles.position[i].z, r = particles.radius[i];
    return z + r > z_lo && z - r < z_hi;
  };
  particles.remove_if([&](std::size_t i) { return in_gap(i) && disc_of(i) < 0; });
  std::vector<int> disc(particles.size(), -1);
  for (std::size_t i = 0; i < particles.size(); ++i) {
    if (in_gap(i)) {
      disc[i] = disc_of(i);
      particles.body[i] = cell_third;
    } else {
      particles.body[i] = particles.position[i].z < z_axis ? cell_bottom : cell_top;
    }
  }

  SlidingCell cell(std::move(particles), box, spec.cell);
  const auto& p = cell.engine().particles();
  std::vector<std::vector<std::size_t>> loose(static_cast<std::size_t>(spec.count));
  for (std::size_t i = 0; i < p.size(); ++i)
    if (disc[i] >= 0 && !p.frozen(i)) loose[static_cast<std::size_t>(disc[i])].push_back(i);
  for (const auto& l : loose) {
    if (l.size() < 3)
      throw InputError(fmt::format("trapped particles: a loose particle of D = {:.3g} m holds {} DEM particles of "
                                   "d0 = {:.3g} m; allowed: D several times d0",
                                   spec.diameter, l.size(), d0));
    out.loose_particles.push_back(l.size());
  }
  out.particles = p.size();
  out.time_step = cell.time_step();
  out.area = cell.area();
  const long planned = cell.planned_steps();
  const long settle = cell.settle_steps();
  const long window_start = settle + static_cast<long>(spec.fit_from * static_cast<double>(planned - settle));
  const long every = spec.cell.record_every;
  if (settle + (window_start - settle + every - 1) / every * every >= planned)
    throw InputError(fmt::format("trapped particles: fit_from = {} leaves no record interval ({} steps) to fit; "
                                 "allowed: a smaller fit_from or record_every",
                                 spec.fit_from, every));
  std::vector<std::vector<Vec3>> window_positions;
  long done = 0;
  // The run's state: the DEM system and the measurements so far (the window
  // positions of every loose particle, one after the other).
  auto save = [&] {
    CheckpointState st;
    cell.engine().save_state(st);
    put_samples(st, "trapped_particles.history", out.history);
    std::vector<Vec3> window;
    for (const auto& w : window_positions) window.insert(window.end(), w.begin(), w.end());
    put_points(st, "trapped_particles.window_positions", window);
    st.put("trapped_particles.tallies", std::vector<double>{double(done), out.peak_tangential_force});
    return st;
  };
  if (checkpoints.from != nullptr) {
    const CheckpointState& st = *checkpoints.from;
    cell.engine().restore_state(st);
    const auto& t = tallies(st, "trapped_particles.tallies", 2);
    done = step_tally(st, "trapped_particles.tallies", t[0]);
    out.peak_tangential_force = t[1];
    out.history = samples<SlidingSample>(st, "trapped_particles.history");
    const auto window = points(st, "trapped_particles.window_positions");
    std::size_t at = 0;
    if (!window.empty())
      for (const auto& l : loose) {
        if (at + l.size() > window.size()) break;
        window_positions.emplace_back(window.begin() + static_cast<std::ptrdiff_t>(at),
                                      window.begin() + static_cast<std::ptrdiff_t>(at + l.size()));
        at += l.size();
      }
    if (at != window.size() || (!window.empty() && window_positions.size() != loose.size()))
      throw InputError(fmt::format("{}: not the state of this trapped-particles run", st.origin));
  } else {
    out.history.push_back(cell.advance(0));
    if (window_start == 0)
      for (const auto& l : loose) window_positions.push_back(unwrapped_positions(cell.engine(), l));
  }
  cell.run([&](const SlidingSample& s, long step, long) {
    done = step;
    out.history.push_back(s);
    out.peak_tangential_force = std::max(out.peak_tangential_force, s.tangential_force);
    if (step >= window_start && step < planned && window_positions.empty())
      for (const auto& l : loose) window_positions.push_back(unwrapped_positions(cell.engine(), l));
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
  double worn_volume = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    if (worn[i] != 0.0 && p.body[i] != cell_third) {
      ++out.worn_first_body;
      worn_volume += 4.0 / 3.0 * std::numbers::pi * p.radius[i] * p.radius[i] * p.radius[i];
    }
  out.band_thickness = worn_volume / (sample.relaxed_volume_fraction * out.area);
  for (std::size_t k = 0; k < loose.size(); ++k) {
    const double r = rigid_fit(window_positions[k], unwrapped_positions(cell.engine(), loose[k])).residual;
    out.loose_residual.push_back(r);
    out.mean_residual += r / static_cast<double>(loose.size());
  }
  out.rolling = out.mean_residual < 1.0 / 3.0;
  return out;
}

}  // namespace wearscale::dem
