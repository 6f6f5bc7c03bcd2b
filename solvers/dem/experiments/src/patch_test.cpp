#include "wearscale/dem/patch_test.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <gsl/gsl_fit.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/amorphous_sample.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/bonds.hpp"
#include "wearscale/dem/hcp_lattice.hpp"
#include "wearscale/dem/simulation.hpp"
#include "wearscale/dem/virial_stress.hpp"

namespace wearscale::dem {

namespace {

constexpr int load_axis = 1;  // y: walls at both ends, periodic across x and z

// The sample between its walls, ready to load: particles at rest, the bottom
// wall fixed and the top wall not yet given a motion.
struct Sample {
  Particles particles;
  Box box;
  std::vector<std::size_t> bottom, top;
  double height = 0.0;  // distance between the walls' inner faces at rest
};

Sample hcp_sample(const PatchTestSpec& s) {
  const double a = s.d0;
  HcpLattice lattice{a, 1, 1, 1};
  const Vec3 cell = lattice.cell();
  // Lattice axes (X, Y, Z = stacking) to sample axes.
  std::array<int, 3> to_sample = s.load_along_c_axis ? std::array<int, 3>{0, 2, 1} : std::array<int, 3>{0, 1, 2};
  std::array<double, 3> want{};  // sample lengths along the lattice axes
  want[0] = s.length * s.d0;
  want[static_cast<std::size_t>(s.load_along_c_axis ? 2 : 1)] = s.length * s.d0;
  want[static_cast<std::size_t>(s.load_along_c_axis ? 1 : 2)] = s.width * s.d0;
  std::array<int, 3> cells{};
  for (std::size_t k = 0; k < 3; ++k) cells[k] = std::max(1, static_cast<int>(std::lround(want[k] / cell[static_cast<int>(k)])));
  lattice.nx = cells[0];
  lattice.ny = cells[1];
  lattice.nz = cells[2];
  const Box lb = lattice.box();
  Sample out;
  for (int k = 0; k < 3; ++k) {
    out.box.lo[to_sample[static_cast<std::size_t>(k)]] = lb.lo[k];
    out.box.hi[to_sample[static_cast<std::size_t>(k)]] = lb.hi[k];
  }
  for (const auto& x : lattice.sites()) {
    Vec3 y{};
    for (int k = 0; k < 3; ++k) y[to_sample[static_cast<std::size_t>(k)]] = x[k];
    out.particles.add({y, 0.5 * s.d0, s.material.density, {}, 0, 0});
  }
  return out;
}

Sample amorphous_sample(const PatchTestSpec& s) {
  AmorphousSpec spec;
  spec.sizes.mode = s.d0;
  spec.sizes.smallest = 0.75 * s.d0;  // §6.2.2
  spec.sizes.largest = 1.25 * s.d0;
  spec.box_size = {s.length * s.d0, s.length * s.d0, s.width * s.d0};
  spec.seed = s.seed;
  auto made = make_amorphous_sample(s.material, spec);
  Sample out;
  out.particles = std::move(made.particles);
  out.box = made.box;
  return out;
}

// Cuts the sample open along the load axis and makes its two walls.
void make_walls(Sample& s, double thickness) {
  s.box.periodic[load_axis] = false;
  double lo = s.particles.position[0][load_axis], hi = lo;
  for (const auto& x : s.particles.position) {
    lo = std::min(lo, x[load_axis]);
    hi = std::max(hi, x[load_axis]);
  }
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    const double y = s.particles.position[i][load_axis];
    if (y < lo + thickness) s.bottom.push_back(i);
    if (y > hi - thickness) s.top.push_back(i);
  }
  s.height = hi - lo - 2.0 * thickness;
}

Sample build(const PatchTestSpec& spec) {
  Sample s = spec.amorphous ? amorphous_sample(spec) : hcp_sample(spec);
  make_walls(s, spec.wall_thickness * spec.d0);
  return s;
}

struct Loading {
  std::unique_ptr<Engine> sim;
  std::vector<std::size_t> inner;  // mobile particles in the middle half: the measured region
  std::vector<double> y0;          // initial load-axis coordinate of every particle
  double inner_volume = 0.0;
  double area = 0.0;               // wall area (the two periodic lengths)
  double height = 0.0;
  int top = 1;
};

Loading prepare(const PatchTestSpec& spec, Sample s, WallMotion top_motion, double damping_fraction) {
  CohesiveLaw law({spec.material});
  const double dt = spec.time_step * law.critical_time_step(s.particles);
  const double damping = damping_fraction * law.critical_damping(s.particles);
  const Vec3 length = s.box.length();
  const double area = length.x * length.z;
  Loading l{make_engine(spec.engine, {std::move(s.particles), s.box, std::make_unique<CohesiveLaw>(std::move(law)),
                                      NeighborSettings{0.1 * spec.d0, 0, true}}),
            {}, {}, 0.0, area, s.height, 1};
  auto& sim = *l.sim;
  sim.set_time_step(dt);
  sim.set_global_damping(damping);
  sim.set_track_virial(true);
  sim.add_wall(std::move(s.bottom), WallMotion::fixed());
  if (top_motion.kind == WallMotion::Kind::Pressure) {
    top_motion.area = area;
    top_motion.damping = damping * static_cast<double>(s.top.size());
  }
  l.top = sim.add_wall(std::move(s.top), top_motion);
  const auto& p = sim.particles();
  double lo = 1e300, hi = -1e300;
  for (std::size_t i = 0; i < p.size(); ++i) {
    l.y0.push_back(p.position[i][load_axis]);
    if (p.wall[i] != no_wall) continue;
    lo = std::min(lo, p.position[i][load_axis]);
    hi = std::max(hi, p.position[i][load_axis]);
  }
  const double quarter = 0.25 * (hi - lo);
  for (std::size_t i = 0; i < p.size(); ++i)
    if (p.wall[i] == no_wall && l.y0[i] > lo + quarter && l.y0[i] < hi - quarter) l.inner.push_back(i);
  l.inner_volume = area * 2.0 * quarter;
  return l;
}

// ε_yy: slope of the load-axis displacement against the initial coordinate
// over the mobile particles (least squares, GSL).
double axial_strain(const Loading& l) {
  std::vector<double> y, u;
  const auto& p = l.sim->particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.wall[i] != no_wall) continue;
    y.push_back(l.y0[i]);
    const double periods = p.image[i][load_axis] * l.sim->box().length()[load_axis];
    u.push_back(p.position[i][load_axis] + periods - l.y0[i]);
  }
  double c0 = 0, c1 = 0, cov00 = 0, cov01 = 0, cov11 = 0, sumsq = 0;
  gsl_fit_linear(y.data(), 1, u.data(), 1, y.size(), &c0, &c1, &cov00, &cov01, &cov11, &sumsq);
  return c1;
}

SymTensor inner_stress(const Loading& l) {
  // The region's volume follows its axial strain.
  return virial_stress(*l.sim, l.inner, l.inner_volume * (1.0 + axial_strain(l)));
}

// The three tests run one after the other; a checkpoint holds which one
// runs, what the finished ones measured, the DEM system of the running one
// and its loop tallies.
enum Phase { elastic_phase = 0, tension_phase = 1, shear_phase = 2 };

CheckpointState patch_state(Phase phase, const PatchTestResult& r, const Engine& sim, std::vector<double> loop) {
  CheckpointState st;
  sim.save_state(st);
  st.put("patch_test.phase", static_cast<double>(phase));
  st.put("patch_test.measured",
         std::vector<double>{double(r.particles), double(r.elastic_steps), r.elastic_converged ? 1.0 : 0.0, r.c11,
                             r.c12, r.young, r.poisson, r.tensile_strength.value_or(std::nan("")),
                             double(r.strength_steps)});
  st.put("patch_test.loop", loop);
  return st;
}

Phase restore_measured(const CheckpointState& st, PatchTestResult& r) {
  const double phase = st.scalar("patch_test.phase");
  if (phase != 0.0 && phase != 1.0 && phase != 2.0)
    throw InputError(fmt::format("{}: patch-test phase {}: not the state of a patch test", st.origin, phase));
  const auto& m = tallies(st, "patch_test.measured", 9);
  r.particles = static_cast<std::size_t>(step_tally(st, "patch_test.measured", m[0]));
  r.elastic_steps = step_tally(st, "patch_test.measured", m[1]);
  r.elastic_converged = m[2] != 0.0;
  r.c11 = m[3];
  r.c12 = m[4];
  r.young = m[5];
  r.poisson = m[6];
  if (!std::isnan(m[7])) r.tensile_strength = m[7];
  r.strength_steps = step_tally(st, "patch_test.measured", m[8]);
  return static_cast<Phase>(static_cast<int>(phase));
}

// Elastic constants are measured on a sample at rest under its load (a
// sample still moving, heated by an unstable time step or behind a wall that
// never stops, is a numerical failure) and, for a lattice, bonded to its
// nearest neighbours only (a refusal naming the smallest valid d0).
void check_elastic_result(const PatchTestSpec& spec, const PatchTestResult& r, const Loading& l, double strain) {
  const std::string dt = fmt::format("{:g} Δt_c", spec.time_step);
  if (!r.elastic_converged)
    throw NumericalError("dem patch test", r.elastic_steps, "top wall displacement",
                         fmt::format("still moving after {} steps under the load, the sample did not come to rest; "
                                     "the time step {} may be unstable for this lattice (the thesis uses 0.1 Δt_c)",
                                     r.elastic_steps, dt));
  // The strain energy ½ σ ε V the load stored, against the kinetic energy left.
  const double stored = 0.5 * spec.load * spec.material.young * std::fabs(strain) * l.area * l.height;
  const double kinetic = l.sim->kinetic_energy();
  if (!(kinetic <= 1e-6 * stored))
    throw NumericalError("dem patch test", r.elastic_steps, "kinetic energy of the loaded sample",
                         fmt::format("{:.3g}, {:.2g} of the strain energy {:.3g}: the wall stopped but the particles "
                                     "still vibrate (at rest it is below 1e-6 of it); the time step {} is unstable for "
                                     "this lattice (the thesis uses 0.1 Δt_c)",
                                     kinetic, kinetic / stored, stored, dt));
  if (!spec.amorphous) {
    // In the loaded lattice each particle still bonds to its 12 nearest
    // neighbours only: none pulled in a second neighbour.
    const auto& p = l.sim->particles();
    std::vector<int> bonds(p.size(), 0);
    for (const auto& [i, j] : bonded_pairs(p, l.sim->box(), BondCriterion::cohesive(CohesiveLaw({spec.material}), 0.5 * spec.d0))) {
      ++bonds[i];
      ++bonds[j];
    }
    const int most = bonds.empty() ? 0 : *std::max_element(bonds.begin(), bonds.end());
    if (most > 12)
      require_hcp_spacing({spec.material}, spec.d0, "patch test", std::fabs(strain));
  }
}

void elastic_test(const PatchTestSpec& spec, PatchTestResult& r, const PatchTestProgress& progress,
                  const RunCheckpoints& checkpoints, const CheckpointState* from) {
  const double pressure = spec.load * spec.material.young;
  auto l = prepare(spec, build(spec), WallMotion::pressed(load_axis, pressure, 1.0, +1), spec.elastic_damping);
  r.particles = l.sim->particles().size();
  // Damped loading until the top wall stops: its displacement changes by
  // less than 1e-5 of itself over a check interval.
  const long chunk = 500;
  double previous = 0.0;
  long steps = 0;
  if (from != nullptr) {
    l.sim->restore_state(*from);
    const auto& t = tallies(*from, "patch_test.loop", 2);
    steps = step_tally(*from, "patch_test.loop", t[0]);
    previous = t[1];
  }
  while (steps < spec.max_elastic_steps) {
    l.sim->run(chunk);
    steps += chunk;
    if (progress) progress("elastic", steps, spec.max_elastic_steps);
    const double now = l.sim->wall(l.top).displacement[load_axis];
    if (steps >= 4 * chunk && std::fabs(now - previous) < 1e-5 * std::fabs(now)) {
      r.elastic_converged = true;
      break;
    }
    previous = now;
    checkpoints.offer(steps, [&] { return patch_state(elastic_phase, r, *l.sim, {double(steps), previous}); });
  }
  r.elastic_steps = steps;
  l.sim->compute_forces();
  const double strain = axial_strain(l);
  const SymTensor s = inner_stress(l);
  const double lateral = 0.5 * (s[0] + s[2]);  // σ_xx and σ_zz (equal for an isotropic sample)
  r.c11 = s[1] / strain;
  r.c12 = lateral / strain;
  check_elastic_result(spec, r, l, strain);
  const auto constants = isotropic_constants(r.c11, r.c12, steps);
  r.young = constants.young;
  r.poisson = constants.poisson;
}

// Pulls (axis 1) or shears (axis 0) the top wall at the strain rate; the peak
// of the stress component `component` in the middle of the sample.
double strength_test(const PatchTestSpec& spec, int direction, int component, PatchTestResult& r,
                     const PatchTestProgress& progress, const std::string& name, const RunCheckpoints& checkpoints,
                     Phase phase, const CheckpointState* from) {
  Sample s = build(spec);
  CohesiveLaw probe({spec.material});
  const double dt = spec.time_step * probe.critical_time_step(s.particles);
  const double rate = spec.strain_rate / dt;  // ε̇ = 1e-5/Δt (§6.2)
  Vec3 v{};
  v[direction] = rate * s.height;
  auto l = prepare(spec, std::move(s), WallMotion::moving(v), spec.strength_damping);
  const double max_strain = spec.max_strain > 0.0 ? spec.max_strain : 3.0 * spec.material.tensile_strength / spec.material.young;
  const long planned = planned_steps(max_strain / spec.strain_rate, "the patch test's strength test");
  double peak = 0.0;
  long done = 0;
  if (from != nullptr) {
    l.sim->restore_state(*from);
    const auto& t = tallies(*from, "patch_test.loop", 2);
    done = step_tally(*from, "patch_test.loop", t[0]);
    peak = t[1];
  }
  const long chunk = 100;
  while (done < planned) {
    l.sim->run(chunk);
    done += chunk;
    const double stress = inner_stress(l)[static_cast<std::size_t>(component)];
    peak = std::max(peak, stress);
    if (progress) progress(name, done, planned);
    if (peak > 0.0 && stress < 0.3 * peak) break;  // failed
    checkpoints.offer(r.elastic_steps + r.strength_steps + done,
                      [&] { return patch_state(phase, r, *l.sim, {double(done), peak}); });
  }
  r.strength_steps += done;
  return peak;
}

}  // namespace

IsotropicConstants isotropic_constants(double c11, double c12, long step) {
  IsotropicConstants out;
  out.poisson = c12 / (c11 + c12);                                                           // ν = C12/(C11 + C12)
  out.young = c11 * (1.0 + out.poisson) * (1.0 - 2.0 * out.poisson) / (1.0 - out.poisson);  // E from C11, ν
  if (!(out.young > 0.0) || !(out.poisson > -1.0 && out.poisson < 0.5))
    throw NumericalError("dem patch test", step, "elastic constants",
                         fmt::format("E = {:.4g}, ν = {:.4g} from C11 = {:.4g}, C12 = {:.4g}: an elastic solid has "
                                     "E > 0 and -1 < ν < 0.5",
                                     out.young, out.poisson, c11, c12));
  return out;
}

double patch_test_d0(const CohesiveMaterial& m) { return 0.6 * critical_diameter(m); }

PatchTestResult run_patch_test(const PatchTestSpec& spec, const PatchTestProgress& progress,
                               const RunCheckpoints& checkpoints) {
  require_modelled(spec.material);
  if (!(spec.d0 > 0.0)) throw InputError(fmt::format("patch test: d0 = {}; allowed: > 0", spec.d0));
  using S = PatchTestSpec;
  const auto within = [](double v, double low, double high, const char* what, const char* allowed) {
    if (!(v >= low && v <= high)) throw InputError(fmt::format("patch test: {} = {:g}; allowed: {}", what, v, allowed));
  };
  within(spec.length, S::min_length, S::max_length, "L (in d0)", "6 … 400");
  within(spec.width, S::min_width, S::max_width, "W (in d0)", "1.25 … 100");
  if (!(spec.time_step > 0.0 && spec.time_step < 1.0))
    throw InputError(fmt::format("patch test: time step = {:g} Δt_c; allowed: (0, 1)", spec.time_step));
  if (!(spec.strain_rate > 0.0 && spec.strain_rate < S::max_strain_rate))
    throw InputError(fmt::format("patch test: strain rate = {:g}; allowed: (0, 0.01)", spec.strain_rate));
  if (spec.max_elastic_steps < S::min_elastic_steps || static_cast<double>(spec.max_elastic_steps) > max_planned_steps)
    throw InputError(fmt::format("patch test: max elastic steps = {}; allowed: {} … {:g}", spec.max_elastic_steps,
                                 S::min_elastic_steps, max_planned_steps));
  if (!(spec.load > 0.0 && spec.load < spec.material.tensile_strength / spec.material.young))
    throw InputError(fmt::format("patch test: load = {} E; allowed: 0 < load < σ_m,N/E = {}", spec.load,
                                 spec.material.tensile_strength / spec.material.young));
  // The elastic test compresses the lattice by about load/E (C11 ≥ E for
  // ν ≤ 1/4 and ν ≥ −1); the measured state is checked as well.
  if (!spec.amorphous) require_hcp_spacing({spec.material}, spec.d0, "patch test", spec.load);
  PatchTestResult r;
  r.d_min = minimum_diameter(spec.material);
  r.d_c = critical_diameter(spec.material);
  const double size = std::max(1.0, spec.d0 / r.d_c);
  r.target_tensile = spec.material.tensile_strength * std::pow(size, -spec.material.scaling_exponent);  // (6.63)
  r.target_shear = spec.material.shear_strength * std::pow(size, -spec.material.scaling_exponent);
  const CheckpointState* from = checkpoints.from;
  const Phase resumed = from != nullptr ? restore_measured(*from, r) : elastic_phase;
  auto from_if = [&](Phase phase) { return resumed == phase ? from : nullptr; };
  if (resumed == elastic_phase) elastic_test(spec, r, progress, checkpoints, from_if(elastic_phase));
  if (spec.strengths) {
    if (resumed <= tension_phase)
      r.tensile_strength = strength_test(spec, load_axis, 1, r, progress, "tension", checkpoints, tension_phase,
                                         from_if(tension_phase));
    r.shear_strength = strength_test(spec, 0, 3, r, progress, "shear", checkpoints, shear_phase, from_if(shear_phase));
  }
  return r;
}

}  // namespace wearscale::dem
