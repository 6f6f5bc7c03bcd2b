#include "wearscale/dem/oxide_asperity.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <string>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/amorphous_sample.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/cell_order.hpp"
#include "wearscale/dem/clusters.hpp"
#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/rigid_fit.hpp"
#include "wearscale/dem/shapes.hpp"
#include "wearscale/dem/simulation.hpp"
#include "wearscale/dem/steady_sliding.hpp"

namespace wearscale::dem {

namespace {

[[noreturn]] void refuse(const std::string& what, double v, const std::string& allowed) {
  throw InputError(fmt::format("oxide asperity: {} = {:g}; allowed: {}", what, v, allowed));
}

double largest_of(const OxideAsperitySpec& s) { return s.largest > 0.0 ? s.largest : 1.25 * s.d0; }

// The SiO2 block carved into layer, cylinder and plate: the layer's centres
// in [0, layer), the cylinder above its tallest particles, the plate above.
struct Heights {
  double axis = 0.0;         // cylinder axis, from the block's bottom
  double plate_bottom = 0.0; // lowest point of the plate
  double block = 0.0;        // block height
  double substrate = 0.0;    // Si thickness available below the block
};

Heights heights(const OxideAsperitySpec& s) {
  Heights h;
  const double c = s.clearance * s.d0;
  h.axis = s.layer_thickness + 0.5 * largest_of(s) + c + 0.5 * s.body_diameter;
  h.plate_bottom = h.axis + 0.5 * s.body_diameter + c;
  h.block = h.plate_bottom + s.plate_thickness * s.d0;
  h.substrate = s.box.z - h.block - 0.5 * s.d0;
  return h;
}

// Mobile particles whose displacement over the window `from` → `to` (all
// particles, unwrapped) the body's rigid motion explains within `tol`.
struct Window {
  std::vector<Vec3> from;
  double sliding = 0.0;
};

// The 1D surface profile: the tops of the substrate and layer particles not in
// the body, highest per d0 × d0 column, averaged over y per x bin.
class SurfaceProfile {
 public:
  SurfaceProfile(const Box& box, double d0, double cap)
      : lo_(box.lo), nx_(std::max(1, static_cast<int>(std::floor(box.length().x / d0)))),
        ny_(std::max(1, static_cast<int>(std::floor(box.length().y / d0)))), cap_(cap),
        wx_(box.length().x / nx_), wy_(box.length().y / ny_), top_(static_cast<std::size_t>(nx_ * ny_)),
        bins_(static_cast<std::size_t>(nx_)) {}

  const std::vector<double>& measure(const Particles& p, const std::vector<char>& in_body, double floor) {
    std::fill(top_.begin(), top_.end(), floor);
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (in_body[i] || (p.body[i] != asperity_substrate && p.body[i] != asperity_layer)) continue;
      if (p.position[i].z > cap_) continue;  // debris above the surface
      const int bx = std::clamp(static_cast<int>(std::floor((p.position[i].x - lo_.x) / wx_)), 0, nx_ - 1);
      const int by = std::clamp(static_cast<int>(std::floor((p.position[i].y - lo_.y) / wy_)), 0, ny_ - 1);
      double& t = top_[static_cast<std::size_t>(bx * ny_ + by)];
      t = std::max(t, p.position[i].z + p.radius[i]);
    }
    for (int bx = 0; bx < nx_; ++bx) {
      double sum = 0.0;
      for (int by = 0; by < ny_; ++by) sum += top_[static_cast<std::size_t>(bx * ny_ + by)];
      bins_[static_cast<std::size_t>(bx)] = sum / ny_;
    }
    return bins_;
  }
  double bin_center(int bx) const { return lo_.x + (bx + 0.5) * wx_; }
  int bins() const { return nx_; }

 private:
  Vec3 lo_;
  int nx_, ny_;
  double cap_, wx_, wy_;
  std::vector<double> top_, bins_;
};

}  // namespace

void check(const OxideAsperitySpec& s) {
  require_modelled(s.oxide);
  require_modelled(s.substrate);
  if (s.interface) require_modelled(*s.interface);
  auto positive = [](double v, const char* what) {
    if (!(v > 0.0) || !std::isfinite(v)) refuse(what, v, "> 0");
  };
  positive(s.d0, "d0");
  positive(s.velocity, "velocity");
  positive(s.time_step, "time step (in Δt_c)");
  positive(s.sliding_distance, "sliding distance");
  positive(s.layer_thickness, "layer thickness");
  positive(s.body_diameter, "body diameter D");
  if (!(s.pressure >= 0.0) || !std::isfinite(s.pressure)) refuse("pressure", s.pressure, "≥ 0");
  if (!(s.settle_distance >= 0.0) || !std::isfinite(s.settle_distance)) refuse("settle distance", s.settle_distance, "≥ 0");
  if (!(s.settle_damping >= 0.0 && s.settle_damping <= 1.0)) refuse("settle damping (of c_c)", s.settle_damping, "[0, 1]");
  if (!(s.track_distance >= 0.0) || !std::isfinite(s.track_distance)) refuse("track distance", s.track_distance, "≥ 0");
  if (s.largest != 0.0 && !(s.largest >= s.d0)) refuse("largest diameter d_l", s.largest, fmt::format("≥ d0 = {:g}", s.d0));
  if (!(s.clearance >= 0.0 && s.clearance < 1.0)) refuse("clearance (in d0)", s.clearance, "[0, 1)");
  if (!(s.plate_thickness >= 1.0 && s.plate_thickness <= 10.0)) refuse("plate thickness (in d0)", s.plate_thickness, "[1, 10]");
  if (!(s.wall_thickness >= 1.0 && s.wall_thickness <= 10.0)) refuse("wall thickness (in d0)", s.wall_thickness, "[1, 10]");
  if (s.record_every < 1) refuse("record_every", static_cast<double>(s.record_every), "≥ 1");
  if (!(s.body_diameter >= 3.0 * s.d0)) refuse("body diameter D", s.body_diameter, fmt::format("≥ 3 d0 = {:g} m", 3.0 * s.d0));
  if (!(s.layer_thickness >= 0.5 * s.d0)) refuse("layer thickness", s.layer_thickness, fmt::format("≥ d0/2 = {:g} m", 0.5 * s.d0));
  if (!(s.box.x >= s.body_diameter + 4.0 * s.d0))
    refuse("box length (x)", s.box.x, fmt::format("≥ D + 4 d0 = {:g} m", s.body_diameter + 4.0 * s.d0));
  if (!(s.box.y >= std::sqrt(3.0) * s.d0)) refuse("box depth (y)", s.box.y, fmt::format("≥ √3 d0 = {:g} m", std::sqrt(3.0) * s.d0));
  const Heights h = heights(s);
  const double need = (s.wall_thickness + 1.5) * s.d0;
  if (!(h.substrate >= need))
    refuse("box height (z)", s.box.z,
           fmt::format("≥ {:g} m: the SiO2 layer, the cylinder with its clearances and the plate take {:g} m, and the Si "
                       "substrate needs its wall and a mobile layer ({:g} m)",
                       h.block + 0.5 * s.d0 + need, h.block + 0.5 * s.d0, need));
}

OxideAsperityResult run_oxide_asperity(const OxideAsperitySpec& spec, const OxideAsperityObserver& observe,
                                       const RunCheckpoints& checkpoints) {
  check(spec);
  require_hcp_spacing({spec.substrate}, spec.d0, "oxide asperity (the Si lattice)");
  const double d0 = spec.d0;
  const Heights h = heights(spec);
  OxideAsperityResult out;

  // The Si lattice, close-packed planes parallel to the surface, whole cells
  // along x and y.
  HcpLattice lattice{d0, std::max(1, static_cast<int>(std::lround(spec.box.x / d0))),
                     std::max(1, static_cast<int>(std::lround(spec.box.y / (std::sqrt(3.0) * d0)))), 1};
  const Vec3 cell = lattice.cell();
  lattice.nz = static_cast<int>(std::ceil(h.substrate / cell.z)) + 1;
  const double size_x = lattice.nx * cell.x, size_y = lattice.ny * cell.y;
  Particles p;
  double si_top = -std::numeric_limits<double>::infinity();
  for (const Vec3& s : lattice.sites()) {
    if (s.z + 0.5 * d0 > h.substrate) continue;
    p.add({s, 0.5 * d0, spec.substrate.density, {}, 1, asperity_substrate});
    si_top = std::max(si_top, s.z + 0.5 * d0);
  }
  out.substrate_particles = p.size();

  // The SiO2 block: relaxed amorphous (§6.2.2), fitted to the lattice's
  // periodic lengths, carved into layer, cylinder and plate.
  const auto sample = make_carving_sample(spec.oxide, d0, spec.largest, {size_x, size_y, h.block}, spec.seed,
                                          spec.relax_tolerance, spec.max_relax_steps, /*numbered_along_cells=*/true);
  out.relaxation_steps = sample.relaxation.repulsion_steps + sample.relaxation.cohesion_steps;
  const Vec3 relaxed = sample.box.length();
  // The relaxed box differs from the lattice's lengths by the relaxation's
  // strain: scaled by their mean s (positions and radii: a similarity, no
  // stress), and by what remains of sx, sy in plane (reported).
  const double sx = size_x / relaxed.x, sy = size_y / relaxed.y, sm = 0.5 * (sx + sy);
  out.relax_strain = std::max(std::abs(sx / sm - 1.0), std::abs(sy / sm - 1.0));
  out.relax_scale = sm;
  const double axis_x = 0.5 * size_x, radius = 0.5 * spec.body_diameter;
  const double base = si_top + 0.5 * d0;  // the block's bottom centre level: touching the Si for d = d0
  for (std::size_t i = 0; i < sample.particles.size(); ++i) {
    const Vec3& x = sample.particles.position[i];
    const double r = sm * sample.particles.radius[i];
    const double u = sm * (x.z - sample.box.lo.z);  // the block's particles are wrapped into [lo, hi)
    int tag = -1;
    if (u < spec.layer_thickness)
      tag = asperity_layer;
    else if (std::hypot((x.x - sample.box.lo.x) * sx - axis_x, u - h.axis) + r <= radius)
      tag = asperity_body;
    else if (u - r >= h.plate_bottom)
      tag = asperity_plate;
    if (tag < 0) continue;
    const std::size_t k = p.add({{(x.x - sample.box.lo.x) * sx, (x.y - sample.box.lo.y) * sy, base + u}, r,
                                 spec.oxide.density, {}, 0, tag});
    p.set_mass(k, sm * sm * sm * sample.particles.mass[i]);  // the sample's density-matched mass
  }
  // Numbered along the cells: the carved SiO2 keeps the random order of its
  // insertion otherwise, and its pairs miss the cache at 10⁵ particles.
  p.reorder(cell_order(p.position, 0.5 * largest_of(spec)));
  std::vector<std::size_t> bottom, plate, body0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.body[i] == asperity_substrate && p.position[i].z <= spec.wall_thickness * d0) bottom.push_back(i);
    if (p.body[i] == asperity_plate) plate.push_back(i);
    if (p.body[i] == asperity_body) body0.push_back(i);
    if (p.body[i] == asperity_layer) ++out.layer_particles;
  }
  out.body_particles = body0.size();
  out.plate_particles = plate.size();
  if (body0.size() < 20 || plate.empty() || out.layer_particles == 0)
    throw InputError(fmt::format("oxide asperity: the cylinder of D = {:g} m holds {} particles of d0 = {:g} m, the plate "
                                 "{}, the layer {}; allowed: D, the plate and the layer several d0",
                                 spec.body_diameter, body0.size(), d0, plate.size(), out.layer_particles));
  out.particles = p.size();
  double z_max = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) z_max = std::max(z_max, p.position[i].z + p.radius[i]);
  Box box;
  box.lo = {0.0, 0.0, lattice.box().lo.z - d0};
  box.hi = {size_x, size_y, std::max(spec.box.z, z_max + d0)};
  box.periodic = {true, true, false};
  out.box = {size_x, size_y, spec.box.z};

  double max_radius = 0.0;
  for (double r : p.radius) max_radius = std::max(max_radius, r);
  CohesiveLaw law({spec.oxide, spec.substrate});
  if (spec.interface) law.set_interface(0, 1, *spec.interface);
  const BondCriterion bond = BondCriterion::cohesive(law, max_radius);
  NeighborSettings neighbors{0.1 * d0, 0, true};
  neighbors.renumber_every = spec.renumber_every;
  const double dt = spec.time_step * law.critical_time_step(p);
  const double c_c = law.critical_damping(p);  // (6.64)
  const auto engine = make_engine(spec.engine, {std::move(p), box, std::make_unique<CohesiveLaw>(law), neighbors});
  Engine& sim = *engine;
  sim.set_time_step(dt);
  out.time_step = dt;
  const double area = size_x * size_y;
  const int bottom_wall = sim.add_wall(std::move(bottom), WallMotion::fixed());
  const int top_wall = sim.add_wall(std::move(plate), WallMotion::pressed(2, spec.pressure, area, +1, {}));
  const long settle = planned_steps(spec.settle_distance / (spec.velocity * dt), "the oxide asperity's settling");
  const long slide = planned_steps(spec.sliding_distance / (spec.velocity * dt), "the oxide asperity's slide");
  const long planned = settle + slide;
  if (settle == 0) refuse("settle distance", spec.settle_distance, "> 0 (the layer bonds to the Si while at rest)");
  out.steps = planned;
  out.substrate_top = si_top;
  sim.set_global_damping(spec.settle_damping * c_c);

  const Particles& q = sim.particles();
  const std::size_t n = q.size();
  // The rolling body: its members, and each particle's membership as a flag
  // (the search's) and as a number (the dumps' column), kept together.
  std::vector<std::size_t> members;
  std::vector<char> in_body(n, 0);
  std::vector<double> body_flag(n, 0.0);
  auto set_members = [&](std::vector<std::size_t> next) {
    for (std::size_t i : members) in_body[i] = 0, body_flag[i] = 0.0;
    members = std::move(next);
    for (std::size_t i : members) in_body[i] = 1, body_flag[i] = 1.0;
  };
  set_members(body0);
  std::vector<std::size_t> all(n);
  for (std::size_t i = 0; i < n; ++i) all[i] = i;
  const double tol = 0.25 * d0;
  const double track = spec.track_distance > 0.0 ? spec.track_distance : 2.0 * d0;
  const double cap = si_top + spec.layer_thickness + 2.0 * d0;
  SurfaceProfile profile(sim.box(), d0, cap);
  Window window;
  double rotation = 0.0, travel = 0.0, surface0 = 0.0;
  OxideAsperitySample last;

  // The body's motion over the window, and its members now.
  auto update_body = [&](double sliding) {
    const auto now = unwrapped_positions(sim, all);
    auto subset = [&](const std::vector<Vec3>& x, const std::vector<std::size_t>& set) {
      std::vector<Vec3> s;
      s.reserve(set.size());
      for (std::size_t i : set) s.push_back(x[i]);
      return s;
    };
    auto fit = rigid_fit(subset(window.from, members), subset(now, members));
    std::vector<std::size_t> kept;
    for (std::size_t i : members)
      if (norm(fit.map(window.from[i]) - now[i]) <= 2.0 * tol) kept.push_back(i);
    if (kept.size() >= 4) fit = rigid_fit(subset(window.from, kept), subset(now, kept));
    rotation += fit.angle_y;
    travel += fit.to.x - fit.from.x;
    // Candidates: old members still moving with the body, and particles that
    // moved with it, clearly (more than 2 tol: not the layer at the contact
    // line, which a rolling body barely moves).
    Particles cand;
    std::vector<std::size_t> index;
    for (std::size_t i = 0; i < n; ++i) {
      if (q.frozen(i)) continue;
      const double miss = norm(fit.map(window.from[i]) - now[i]);
      if (miss > tol) continue;
      if (!in_body[i] && norm(now[i] - window.from[i]) < 2.0 * tol) continue;
      index.push_back(i);
      cand.add({q.position[i], q.radius[i], 1.0, {}, q.material[i], in_body[i] ? 1 : 0});
    }
    std::vector<std::size_t> next;
    if (!index.empty()) {
      const auto clusters = find_clusters(cand, sim.box(), bond);
      // The body: the cluster holding most of the old members.
      std::vector<std::size_t> old_in(clusters.clusters.size(), 0);
      for (std::size_t k = 0; k < index.size(); ++k)
        if (in_body[index[k]]) ++old_in[clusters.label[k]];
      const auto best = static_cast<std::size_t>(std::max_element(old_in.begin(), old_in.end()) - old_in.begin());
      if (old_in[best] > 0)
        for (std::size_t k : clusters.clusters[best].members) next.push_back(index[k]);
    }
    set_members(std::move(next));
    window.from = now;
    window.sliding = sliding;
  };

  auto sample_now = [&](double sum_t, double sum_n, long summed) {
    OxideAsperitySample s;
    s.time = sim.time();
    s.sliding = sim.wall(top_wall).displacement.x;
    s.tangential_force = summed > 0 ? sum_t / static_cast<double>(summed) : 0.0;
    s.normal_force = summed > 0 ? sum_n / static_cast<double>(summed) : 0.0;
    s.kinetic_energy = sim.kinetic_energy();
    s.body_particles = static_cast<double>(members.size());
    for (std::size_t i : members)
      if (q.body[i] != asperity_body) s.picked_up += 1.0;
    s.rotation = rotation;
    s.travel = travel;
    // The trench: the strip the body's contact has passed, from its start to
    // half a radius behind its centre now (outside its footprint).
    const double strip = std::min(travel - 0.5 * radius, size_x - spec.body_diameter);
    if (strip > 0.0 && surface0 > 0.0) {
      const auto& bins = profile.measure(q, in_body, si_top);
      double sum = 0.0, lowest = std::numeric_limits<double>::infinity();
      int count = 0;
      for (int b = 0; b < profile.bins(); ++b) {
        double ahead = std::fmod(profile.bin_center(b) - axis_x, size_x);
        if (ahead < 0.0) ahead += size_x;
        if (ahead > strip) continue;
        sum += bins[static_cast<std::size_t>(b)];
        lowest = std::min(lowest, bins[static_cast<std::size_t>(b)]);
        ++count;
      }
      if (count > 0) {
        s.trench_depth = surface0 - sum / count;
        s.trench_max_depth = surface0 - lowest;
      }
    }
    if (!std::isfinite(s.tangential_force) || !std::isfinite(s.normal_force) || !std::isfinite(s.kinetic_energy))
      throw NumericalError("oxide asperity", sim.step_count(), "wall forces",
                           fmt::format("F_T = {}, F_N = {}, E_k = {}", s.tangential_force, s.normal_force,
                                       s.kinetic_energy));
    return s;
  };

  long step = 0;
  // The run's state: the DEM system, the body, its window and what was measured.
  auto save = [&] {
    CheckpointState st;
    sim.save_state(st);
    put_samples(st, "oxide.history", out.history);
    put_indices(st, "oxide.members", members);
    put_points(st, "oxide.window", window.from);
    st.put("oxide.tallies", std::vector<double>{double(step), rotation, travel, surface0, window.sliding,
                                                out.reached_substrate_at});
    return st;
  };
  if (checkpoints.from != nullptr) {
    const CheckpointState& st = *checkpoints.from;
    sim.restore_state(st);
    const auto& t = tallies(st, "oxide.tallies", 6);
    step = step_tally(st, "oxide.tallies", t[0]);
    rotation = t[1];
    travel = t[2];
    surface0 = t[3];
    window.sliding = t[4];
    out.reached_substrate_at = t[5];
    out.history = samples<OxideAsperitySample>(st, "oxide.history");
    auto kept = indices(st, "oxide.members");
    for (std::size_t i : kept)
      if (i >= n) throw InputError(fmt::format("{}: oxide.members names particle {} of {}", st.origin, i, n));
    set_members(std::move(kept));
    window.from = points(st, "oxide.window");
    if (out.history.empty() || (!window.from.empty() && window.from.size() != n))
      throw InputError(fmt::format("{}: not an oxide-asperity state of this system", st.origin));
    last = out.history.back();
  } else {
    out.history.push_back(sample_now(0.0, 0.0, 0));
  }
  while (step < planned) {
    const long chunk = std::min(spec.record_every, step < settle ? settle - step : planned - step);
    double sum_t = 0.0, sum_n = 0.0;
    long summed = 0;
    sim.run(chunk, [&](long) {
      sum_t += 0.5 * (sim.wall(bottom_wall).force.x - sim.wall(top_wall).force.x);
      sum_n += 0.5 * (sim.wall(top_wall).force.z - sim.wall(bottom_wall).force.z);
      ++summed;
    });
    step += chunk;
    const double sliding = sim.wall(top_wall).displacement.x;
    if (step == settle) {
      // Loaded and at rest: undamped sliding from here; the reference surface
      // (away from the body's footprint) and the body's first window.
      sim.set_global_damping(0.0);
      sim.set_wall_velocity(top_wall, 0, spec.velocity);
      const auto& bins = profile.measure(q, in_body, si_top);
      double sum = 0.0;
      int count = 0;
      for (int b = 0; b < profile.bins(); ++b)
        if (std::abs(profile.bin_center(b) - axis_x) > radius) {
          sum += bins[static_cast<std::size_t>(b)];
          ++count;
        }
      surface0 = count > 0 ? sum / count : si_top;
      window.from = unwrapped_positions(sim, all);
      window.sliding = sliding;
    } else if (step > settle && (sliding - window.sliding >= track || step == planned) && !members.empty()) {
      update_body(sliding);
    }
    last = sample_now(sum_t, sum_n, summed);
    out.history.push_back(last);
    if (out.reached_substrate_at < 0.0 && last.trench_max_depth > 0.0 &&
        surface0 - last.trench_max_depth <= si_top + 0.25 * d0)
      out.reached_substrate_at = last.sliding;
    if (observe) observe(sim, last, step, planned, body_flag);
    if (step < planned) checkpoints.offer(step, save);
  }

  out.surface_height = surface0;
  out.layer_measured = surface0 - si_top;
  const SteadySliding steady = steady_sliding(out.history);
  out.friction = steady.friction;
  if (steady.samples > 0) {
    out.mean_tangential_force = steady.tangential_force;
    out.mean_normal_force = steady.normal_force;
  }
  out.final_body = last.body_particles;
  out.final_picked_up = last.picked_up;
  out.rotation = rotation;
  out.travel = travel;
  out.rolling_ratio = travel != 0.0 ? std::abs(rotation) * radius / std::abs(travel) : 0.0;
  out.trench_depth = last.trench_depth;
  out.trench_max_depth = last.trench_max_depth;
  return out;
}

}  // namespace wearscale::dem
