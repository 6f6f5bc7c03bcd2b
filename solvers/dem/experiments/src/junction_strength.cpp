#include "wearscale/dem/junction_strength.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/amorphous_sample.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/rigid_fit.hpp"
#include "wearscale/dem/shapes.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

namespace {

constexpr int bottom_body = 0, junction_body = 1, top_body = 2;

[[noreturn]] void refuse(const std::string& what, double value, const std::string& allowed) {
  throw InputError(fmt::format("junction strength: {} = {:g}; allowed: {}", what, value, allowed));
}

void check(const JunctionStrengthSpec& s) {
  require_modelled(s.top);
  require_modelled(s.bottom);
  const auto& c = s.cell;
  if (!(c.d0 > 0.0) || !std::isfinite(c.d0)) refuse("d0", c.d0, "> 0");
  if (s.arrangement == Arrangement::Hcp) require_hcp_spacing({s.top, s.bottom}, c.d0, "junction strength");
  if (c.length < 6) refuse("cell length (in d0)", c.length, "≥ 6");
  if (c.height < 4) refuse("cell height (in √3 d0)", c.height, "≥ 4");
  if (c.depth < 1) refuse("cell depth (in HCP cells)", c.depth, "≥ 1");
  if (!(c.gap > 0.0 && c.gap < 0.8)) refuse("gap (fraction of the cell height)", c.gap, "(0, 0.8)");
  if (!(c.wall_thickness >= 0.5)) refuse("wall thickness (in d0)", c.wall_thickness, "≥ 0.5");
  const double h = c.height * std::sqrt(3.0) * c.d0;
  const double solid = 0.5 * (1.0 - c.gap) * h;
  if (solid < (c.wall_thickness + 1.0) * c.d0)
    refuse("gap (fraction of the cell height)", c.gap,
           fmt::format("at most {:.3g}: each surface must be thicker than its wall plus one particle",
                       1.0 - 2.0 * (c.wall_thickness + 1.0) * c.d0 / h));
  if (!(s.contact_ratio > 0.0 && s.contact_ratio <= 1.0)) refuse("contact ratio D/L", s.contact_ratio, "(0, 1]");
  if (s.contact_ratio * c.length < 1.0)
    refuse("contact ratio D/L", s.contact_ratio, fmt::format("≥ 1/{} (at least one particle across)", c.length));
  if (!(s.pressure >= 0.0) || !std::isfinite(s.pressure)) refuse("normal pressure p_N", s.pressure, "≥ 0 Pa");
  if (!(s.velocity > 0.0) || !std::isfinite(s.velocity)) refuse("velocity", s.velocity, "> 0 m/s");
  if (!(s.time_step > 0.0 && s.time_step < 1.0)) refuse("time step (in Δt_c)", s.time_step, "(0, 1)");
  if (!(s.settle_distance >= 0.0)) refuse("settle distance (in L)", s.settle_distance, "≥ 0");
  if (!(s.sliding_distance > 0.0)) refuse("sliding distance (in L)", s.sliding_distance, "> 0");
  if (!(s.steady_from >= 0.0 && s.steady_from < 1.0)) refuse("steady window start (fraction of the slide)", s.steady_from, "[0, 1)");
  if (s.record_every < 1) refuse("record_every", static_cast<double>(s.record_every), "≥ 1");
}

struct Rigid2D {
  double angle = 0.0;     // rotation about y [rad]
  double residual = 0.0;  // RMS misfit / RMS displacement
};

// The rotation about y (and translation) that best maps a onto b in the x–z
// plane: closed-form 2D Procrustes.
Rigid2D rigid_fit_xz(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  const double n = static_cast<double>(a.size());
  Vec3 ca{}, cb{};
  for (std::size_t k = 0; k < a.size(); ++k) {
    ca += a[k];
    cb += b[k];
  }
  ca *= 1.0 / n;
  cb *= 1.0 / n;
  double s = 0.0, c = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Vec3 p = a[k] - ca, q = b[k] - cb;
    s += q.x * p.z - q.z * p.x;
    c += q.x * p.x + q.z * p.z;
  }
  Rigid2D out;
  out.angle = std::atan2(s, c);
  const double cs = std::cos(out.angle), sn = std::sin(out.angle);
  double misfit = 0.0, moved = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const Vec3 p = a[k] - ca, q = b[k] - cb;
    const double rx = p.x * cs + p.z * sn, rz = -p.x * sn + p.z * cs;
    misfit += (rx - q.x) * (rx - q.x) + (rz - q.z) * (rz - q.z);
    moved += (q.x - p.x) * (q.x - p.x) + (q.z - p.z) * (q.z - p.z);
  }
  out.residual = moved > 0.0 ? std::sqrt(misfit / moved) : 0.0;
  return out;
}

// The unbroken block the cell is carved from: its particles (masses at
// `density`), periodic box across x and y, the height it fills from
// `bottom`, and the level of the interface between the two surfaces.
struct CellBlock {
  Particles particles;
  Box box;
  double bottom = 0.0, height = 0.0, interface = 0.0, density = 0.0;
};

// The HCP block with its close-packed planes in x–z: lattice (x, y, z) →
// world (x, z, y), so the lattice's c axis runs across the cell (y); the
// interface lies midway between the two rows of sites around mid-height.
CellBlock hcp_block(const JunctionStrengthSpec& spec) {
  const auto& cell = spec.cell;
  const double d0 = cell.d0;
  HcpLattice lattice{d0, cell.length, cell.height, cell.depth};
  const Box lb = lattice.box();
  CellBlock out;
  out.height = lb.hi.y - lb.lo.y;
  out.density = spec.bottom.density;
  std::vector<double> levels;
  for (const Vec3& s : lattice.sites()) {
    const Vec3 x{s.x, s.z - lb.lo.z, s.y};
    out.particles.add({x, 0.5 * d0, out.density, {}, 0, 0});
    levels.push_back(x.z);
  }
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end(), [&](double a, double b) { return b - a < 1e-6 * d0; }),
               levels.end());
  const auto above_mid = std::upper_bound(levels.begin(), levels.end(), 0.5 * out.height);
  out.interface = 0.5 * (*(above_mid - 1) + *above_mid);
  out.box.lo = {0.0, 0.0, 0.0};
  out.box.hi = {lb.hi.x - lb.lo.x, lb.hi.z - lb.lo.z, out.height};
  return out;
}

// An amorphous block of the HCP cell's size (§6.2.2: sizes 0.75-1.25 d0
// about d0, relaxed in a periodic box with the bottom material), cut open
// across z; the interface at mid-height.
CellBlock amorphous_block(const JunctionStrengthSpec& spec) {
  const auto& cell = spec.cell;
  const Vec3 hcp = HcpLattice{cell.d0, cell.length, cell.height, cell.depth}.cell();
  const Vec3 size{cell.length * hcp.x, cell.depth * hcp.z, cell.height * hcp.y};
  auto made = make_carving_sample(spec.bottom, cell.d0, 0.0, size, spec.seed, spec.relax_tolerance, spec.max_relax_steps);
  CellBlock out;
  out.particles = std::move(made.particles);
  out.box = made.box;
  out.density = spec.bottom.density;
  const auto [lo, hi] = extent(out.particles, 2);
  out.bottom = lo;
  out.height = hi - lo;
  out.interface = lo + 0.5 * out.height;
  return out;
}

}  // namespace

std::string JunctionStrengthResult::verdict() const {
  switch (outcome) {
    case Outcome::Flattened: return "flattened";
    case Outcome::Detached: return "detached";
    case Outcome::Sheared: return "sheared";
  }
  return "sheared";
}

double contact_ratio_at(const Engine& sim, double z_mid, double d0) {
  const auto& p = sim.particles();
  const double lo = sim.box().lo.x, length = sim.box().length().x;
  const auto bins = static_cast<long>(std::ceil(16.0 * length / d0));
  const double w = length / static_cast<double>(bins);
  std::vector<char> covered(static_cast<std::size_t>(bins), 0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.frozen(i) || std::abs(p.position[i].z - z_mid) >= 0.5 * d0) continue;
    const double a = (p.position[i].x - lo - p.radius[i]) / w, b = (p.position[i].x - lo + p.radius[i]) / w;
    for (auto k = static_cast<long>(std::floor(a + 0.5)); k < static_cast<long>(std::floor(b + 0.5)); ++k)
      covered[static_cast<std::size_t>(((k % bins) + bins) % bins)] = 1;
  }
  return static_cast<double>(std::count(covered.begin(), covered.end(), 1)) / static_cast<double>(bins);
}

JunctionStrengthResult run_junction_strength(const JunctionStrengthSpec& spec, const JunctionStrengthObserver& observe,
                                             const RunCheckpoints& checkpoints) {
  check(spec);
  const auto& cell = spec.cell;
  const double d0 = cell.d0;
  JunctionStrengthResult out;

  CellBlock block = spec.arrangement == Arrangement::Hcp ? hcp_block(spec) : amorphous_block(spec);
  const double length = block.box.length().x, depth = block.box.length().y, height = block.height;
  const double z_interface = block.interface;
  const double gap = cell.gap * height;
  const double diameter = spec.contact_ratio * length;
  const double x_mid = block.box.lo.x + 0.5 * length;

  const bool two_materials = spec.top.name != spec.bottom.name;
  std::vector<CohesiveMaterial> table{spec.bottom};
  if (two_materials) table.push_back(spec.top);
  // The two surfaces and the junction column between them: the particles
  // centred in the gap are removed but for those within D/2 of the middle.
  Particles& particles = block.particles;
  auto in_gap = [&](std::size_t i) { return std::abs(particles.position[i].z - z_interface) < 0.5 * gap; };
  particles.remove_if([&](std::size_t i) {
    const bool in_column =
        std::abs(particles.position[i].x - x_mid) <= 0.5 * diameter + 1e-9 * d0 || spec.contact_ratio >= 1.0;
    return in_gap(i) && !in_column;
  });
  for (std::size_t i = 0; i < particles.size(); ++i) {
    const bool top = particles.position[i].z > z_interface;
    const CohesiveMaterial& m = top ? spec.top : spec.bottom;
    particles.material[i] = top && two_materials ? 1 : 0;
    particles.body[i] = in_gap(i) ? junction_body : (top ? top_body : bottom_body);
    // The block's masses are those of its packing at the bottom material's
    // density; each side takes its own.
    particles.set_mass(i, particles.mass[i] * m.density / block.density);
    particles.velocity[i] = {};
    particles.omega[i] = {};
  }
  Box box = block.box;
  box.lo.z = block.bottom - d0;
  box.hi.z = block.bottom + height + d0;
  box.periodic = {true, true, false};

  const auto [z_min, z_max] = extent(particles, 2);
  auto bottom = indices_inside(particles, below(2, z_min + cell.wall_thickness * d0));
  auto top = indices_inside(particles, above(2, z_max - cell.wall_thickness * d0));
  CohesiveLaw law(table);
  const double dt = spec.time_step * law.critical_time_step(particles);
  double wall_mass = 0.0;
  for (std::size_t i : top) wall_mass += particles.mass[i];
  const auto engine = make_engine(spec.engine, {std::move(particles), box, std::make_unique<CohesiveLaw>(std::move(law)),
                                                NeighborSettings{0.1 * d0, 0, true, spec.history_of_touching_pairs_only}});
  Engine& sim = *engine;
  sim.set_time_step(dt);
  const double area = length * depth;  // A0 = L B  (7.1)
  // The pressed wall's normal motion is damped critically on the cell's
  // stiffness E A0 / height (softer material), so p_N settles without ringing;
  // the particles themselves have no global damping (§7.1.1).
  const double stiffness = std::min(spec.top.young, spec.bottom.young) * area / height;
  auto pressed = WallMotion::pressed(2, spec.pressure, area, +1);
  pressed.damping = 2.0 * std::sqrt(stiffness * wall_mass);
  const int bottom_wall = sim.add_wall(std::move(bottom), WallMotion::fixed());
  const int top_wall = sim.add_wall(std::move(top), pressed);

  std::vector<std::size_t> junction;
  for (std::size_t i = 0; i < sim.particles().size(); ++i)
    if (sim.particles().body[i] == junction_body && !sim.particles().frozen(i)) junction.push_back(i);
  out.length = length;
  out.depth = depth;
  out.height = height;
  out.gap = gap;
  out.particles = sim.particles().size();
  out.junction_particles = junction.size();
  out.time_step = dt;
  if (junction.empty())
    refuse("contact ratio D/L", spec.contact_ratio, "large enough for the junction to hold a particle");
  auto mid_plane = [&] { return z_interface + 0.5 * sim.wall(top_wall).displacement.z; };
  out.initial_contact_ratio = contact_ratio_at(sim, mid_plane(), d0);

  // Forces averaged over each record interval: p_T from both walls, whose
  // mean cancels the inertia of the sample between them.
  double sum_t = 0.0, sum_n = 0.0;
  long summed = 0;
  auto accumulate = [&](long) {
    sum_t += 0.5 * (sim.wall(bottom_wall).force.x - sim.wall(top_wall).force.x);
    sum_n += 0.5 * (sim.wall(top_wall).force.z - sim.wall(bottom_wall).force.z);
    ++summed;
  };
  const long settle_steps = planned_steps(spec.settle_distance * length / (spec.velocity * dt), "the junction's settling");
  const long slide_steps = planned_steps(spec.sliding_distance * length / (spec.velocity * dt), "the junction's slide");
  const long planned = settle_steps + slide_steps;
  const long window_start = settle_steps + static_cast<long>(spec.steady_from * static_cast<double>(slide_steps));
  std::vector<Vec3> window_positions;
  double window_sliding = 0.0, steady_sum = 0.0, normal_sum = 0.0;
  long steady_count = 0, slide_count = 0;
  long step = 0;
  // The run's state: the DEM system and the measurements so far.
  auto save = [&] {
    CheckpointState st;
    sim.save_state(st);
    put_samples(st, "junction.history", out.history);
    put_points(st, "junction.window_positions", window_positions);
    st.put("junction.tallies", std::vector<double>{double(step), out.loaded_contact_ratio, out.peak_tangential,
                                                   window_sliding, steady_sum, normal_sum, double(steady_count),
                                                   double(slide_count)});
    return st;
  };
  if (checkpoints.from != nullptr) {
    const CheckpointState& st = *checkpoints.from;
    sim.restore_state(st);
    const auto& t = tallies(st, "junction.tallies", 8);
    if (sim.particles().size() != out.particles)
      throw InputError(fmt::format("{}: not the state of this junction run", st.origin));
    step = step_tally(st, "junction.tallies", t[0]);
    out.loaded_contact_ratio = t[1];
    out.peak_tangential = t[2];
    window_sliding = t[3];
    steady_sum = t[4];
    normal_sum = t[5];
    steady_count = static_cast<long>(t[6]);
    slide_count = static_cast<long>(t[7]);
    out.history = samples<JunctionSample>(st, "junction.history");
    window_positions = points(st, "junction.window_positions");
  }
  while (step < planned) {
    if (step == settle_steps) {
      out.loaded_contact_ratio = contact_ratio_at(sim, mid_plane(), d0);
      sim.set_wall_velocity(top_wall, 0, spec.velocity);  // start sliding
    }
    const long chunk = std::min({spec.record_every, planned - step, step < settle_steps ? settle_steps - step : planned});
    sum_t = sum_n = 0.0;
    summed = 0;
    sim.run(chunk, accumulate);
    step += chunk;
    JunctionSample s;
    s.time = sim.time();
    s.sliding = sim.wall(top_wall).displacement.x;
    s.tangential_force = sum_t / static_cast<double>(summed);
    s.normal_force = sum_n / static_cast<double>(summed);
    s.kinetic_energy = sim.kinetic_energy();
    out.history.push_back(s);
    if (step > settle_steps) {
      out.peak_tangential = std::max(out.peak_tangential, s.tangential_force / area);
      normal_sum += s.normal_force / area;
      ++slide_count;
      if (step > window_start) {
        steady_sum += s.tangential_force / area;
        ++steady_count;
      }
    }
    if (step >= window_start && window_positions.empty()) {
      window_positions = unwrapped_positions(sim, junction);
      window_sliding = s.sliding;
    }
    if (observe) observe(sim, s, step, planned);
    if (step < planned) checkpoints.offer(step, save);
  }
  if (settle_steps == 0 && out.loaded_contact_ratio == 0.0) out.loaded_contact_ratio = out.initial_contact_ratio;
  out.steps = planned;
  out.steady_tangential = steady_count > 0 ? steady_sum / static_cast<double>(steady_count) : out.peak_tangential;
  out.normal = slide_count > 0 ? normal_sum / static_cast<double>(slide_count) : 0.0;
  out.final_contact_ratio = contact_ratio_at(sim, mid_plane(), d0);

  // Rolling without slip between a fixed and a moving surface a gap g apart
  // turns the junction by slide/g: rolling_rate ≈ 1.
  const auto fit = rigid_fit_xz(window_positions, unwrapped_positions(sim, junction));
  const double slid = sim.wall(top_wall).displacement.x - window_sliding;
  const double current_gap = gap + sim.wall(top_wall).displacement.z;
  out.rigid_residual = fit.residual;
  out.rolling_rate = slid > 0.0 ? fit.angle * current_gap / slid : 0.0;
  // Flattened: the junction grew by more than two particles and a fifth of
  // its size (a sheared junction smears by about a particle).
  if (out.final_contact_ratio > std::max(out.initial_contact_ratio + 2.0 * d0 / length, 1.2 * out.initial_contact_ratio))
    out.outcome = JunctionStrengthResult::Outcome::Flattened;
  else if (out.rigid_residual < 1.0 / 3.0 && out.rolling_rate > 0.5)
    out.outcome = JunctionStrengthResult::Outcome::Detached;
  else
    out.outcome = JunctionStrengthResult::Outcome::Sheared;
  return out;
}

JunctionLawFit fit_junction_law(const std::vector<JunctionPoint>& points) {
  constexpr double full_contact = 0.95;
  JunctionLawFit f;
  f.runs = points.size();
  if (points.empty()) throw InputError("junction law fit: no junction run; allowed: at least one run");
  // σ of p_T = (A/A0) σ (7.9) on the peak p_T: over the runs whose junction
  // kept its size (A known: the loaded contact ratio), or, when every junction
  // was flattened, over all runs at their final contact ratio.
  bool any_kept = false;
  for (const auto& p : points) any_kept = any_kept || !p.flattened;
  auto area_of = [&](const JunctionPoint& p) { return any_kept ? p.loaded_ratio : p.final_ratio; };
  auto in_sigma_fit = [&](const JunctionPoint& p) { return !any_kept || !p.flattened; };
  double cp = 0.0, cc = 0.0, full = 0.0;
  std::size_t full_runs = 0;
  for (const auto& p : points) {
    if (in_sigma_fit(p)) {
      cp += area_of(p) * p.peak;
      cc += area_of(p) * area_of(p);
    }
    if (p.initial_ratio >= 0.999) {
      full += p.peak;
      ++full_runs;
    }
  }
  if (!(cp > 0.0))
    throw InputError("junction law fit: no run carried a tangential stress p_T > 0; allowed: runs that resist sliding");
  f.shear_strength = cp / cc;
  f.full_contact_peak = full_runs > 0 ? full / static_cast<double>(full_runs) : 0.0;
  auto relative_rms = [](const std::vector<std::pair<double, double>>& got_want) {
    double s = 0.0;
    for (const auto& [got, want] : got_want) s += want != 0.0 ? (got - want) * (got - want) / (want * want) : 0.0;
    return got_want.empty() ? 0.0 : std::sqrt(s / static_cast<double>(got_want.size()));
  };
  std::vector<std::pair<double, double>> res;
  for (const auto& p : points)
    if (in_sigma_fit(p)) res.emplace_back(p.peak, area_of(p) * f.shear_strength);
  f.shear_strength_rms = relative_rms(res);

  // The sliding strength: steady p_T = (A/A0) σ_steady over the D = L runs
  // (full contact: the interface's own sliding strength), else the σ runs.
  double cs = 0.0, cc_s = 0.0;
  for (const auto& p : points)
    if (full_runs > 0 ? p.initial_ratio >= 0.999 : in_sigma_fit(p)) {
      cs += area_of(p) * p.steady;
      cc_s += area_of(p) * area_of(p);
    }
  f.steady_strength = cc_s > 0.0 ? cs / cc_s : 0.0;

  // p_crit of A/A0 = p_N/p_crit (7.6) on the runs whose junction the load
  // crushed before sliding (loaded A/A0 above 1.2 D/L) short of full contact
  // (A/A0 → 1 only says p_crit ≤ p_N). Spreading during sliding is the d*
  // effect the model leaves aside (§7.1.2), so it does not enter.
  auto crushed = [](const JunctionPoint& p) {
    return p.pressure > 0.0 && p.loaded_ratio > 1.2 * p.initial_ratio && p.loaded_ratio < full_contact;
  };
  double pc = 0.0, pp = 0.0, ps = 0.0;
  for (const auto& p : points) {
    if (p.flattened) ++f.flattened;
    if (p.flattened && p.final_ratio >= full_contact) ++f.saturated;
    if (crushed(p)) {
      ++f.crushed;
      pc += p.pressure * p.loaded_ratio;
      pp += p.pressure * p.pressure;
      ps += p.pressure * p.steady;
    }
  }
  if (f.crushed > 0) {
    f.p_crit = pp / pc;
    f.p_crit_source = "runs crushed by the load";
    f.mu0_direct = ps / pp;
    res.clear();
    for (const auto& p : points)
      if (crushed(p)) res.emplace_back(p.loaded_ratio, p.pressure / f.p_crit);
    f.p_crit_rms = relative_rms(res);
  } else {
    f.p_crit = f.shear_strength;  // σ_m,c = σ: p_crit = σ (7.5), as the thesis assumes after (7.10)
    f.p_crit_source = "σ_m,c = σ (7.5): no run crushed by the load short of full contact";
  }
  // μ0 = σ_dyn(p_crit)/p_crit (9.13) with the DEM's sliding strength; the
  // model's p_T,min = μ0 p_N (7.10).
  f.mu0 = (f.steady_strength > 0.0 ? f.steady_strength : f.shear_strength) / f.p_crit;
  return f;
}

}  // namespace wearscale::dem
