// The DEM drivers on the LAMMPS engine over the ranks of `mpirun -np P`: one
// run spread over every rank by LAMMPS' domain decomposition (rank 0 drives
// it, the others serve its calls), against the same driver on wearscale's
// own engine (on rank 0); and each study's state saved mid-run and restored
// into a system set up again, on the same ranks, against the run that never
// stopped. Reduced sizes; exit 0 when the figures agree.
//   mpirun -np P mpi_dem_lammps patch | junction-kept | junction-touching | rough-shear | resume
//                               | resume-rough-shear | resume-trapped | resume-oxide
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "../dem/captured_states.hpp"
#include "../dem/reduced_oxide_asperity.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/dem/lammps_engine.hpp"
#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/dem/patch_test.hpp"
#include "wearscale/dem/rough_shear.hpp"
#include "wearscale/dem/trapped_particles.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {

bool within(const char* what, double lammps, double house, double bound) {
  const double relative = std::fabs(lammps - house) / std::fabs(house);
  std::printf("%s: lammps %.6g, wearscale %.6g, difference %.3g %% (bound %.3g %%) on %d rank(s)\n", what, lammps, house,
              100.0 * relative, 100.0 * bound, mpi::size());
  return relative <= bound;
}

bool patch() {
  PatchTestSpec s;
  s.material = patch_test_targets();
  s.material.poisson = 0.1;
  s.d0 = 90.0;
  s.length = 15.0;
  s.strengths = false;
  const auto house = run_patch_test(s);
  s.engine = "lammps";
  const auto lmp = run_patch_test(s);
  return within("E", lmp.young, house.young, 0.01) & within("nu", lmp.poisson, house.poisson, 0.01);
}

// The full-contact cell of Fig. 7.2 (D = L, p_N = 0), slid past its first slip.
JunctionStrengthSpec full_contact(bool touching) {
  JunctionStrengthSpec s;
  s.top = s.bottom = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 1.5e-9;
  s.contact_ratio = 1.0;
  s.velocity = 50.0;
  s.settle_distance = 0.02;
  s.sliding_distance = 0.4;
  s.history_of_touching_pairs_only = touching;
  return s;
}

bool junction(bool touching) {
  auto s = full_contact(touching);
  const auto house = run_junction_strength(s);
  s.engine = "lammps";
  const auto lmp = run_junction_strength(s);
  return within(touching ? "peak p_T (touching)" : "peak p_T (kept)", lmp.peak_tangential, house.peak_tangential, 0.03);
}

bool rough_shear() {
  RoughShearSpec s;
  s.cell.material = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 3e-9;
  s.cell.box = {20 * 3e-9, 3.5 * 3e-9, 14 * 3e-9};
  s.cell.pressure = 0.5e9;
  s.cell.velocity = 100.0;
  s.cell.sliding_distance = 8 * 3e-9;
  s.cell.settle_distance = 3e-9;
  s.roughness = 0.04;
  const auto house = run_rough_shear(s);
  s.cell.engine = "lammps";
  const auto lmp = run_rough_shear(s);
  return within("mean mu", lmp.friction, house.friction, 0.05);
}

// A state saved halfway and restored into a system set up again continues
// bit for bit as the run that never stopped (same ranks).
bool resume() {
  auto s = full_contact(false);
  s.engine = "lammps";
  s.sliding_distance = 0.1;
  CheckpointState saved;
  long saved_at = 0;
  RunCheckpoints save;
  save.at_sample = [&](long step, const std::function<CheckpointState()>& make) {
    if (saved_at == 0 && step >= 1000) {
      saved = make();
      saved_at = step;
    }
  };
  const auto whole = run_junction_strength(s, {}, save);
  RunCheckpoints from;
  saved.origin = "the saved state";
  from.from = &saved;
  // The step the state holds (as the studies' checkpointer sets it).
  saved.step = saved_at;
  const auto resumed = run_junction_strength(s, {}, from);
  // And saving did not move the run off its course: the same bits as one that never saved.
  const auto plain = run_junction_strength(s);
  auto same_as = [&](const JunctionStrengthResult& r) {
    return whole.history.size() == r.history.size() &&
           std::memcmp(whole.history.data(), r.history.data(), whole.history.size() * sizeof(JunctionSample)) == 0;
  };
  const bool same = same_as(resumed), undisturbed = same_as(plain);
  std::printf("resumed at step %ld of %ld: %s; saving %s (last p_T %.17g / %.17g / %.17g) on %d rank(s)\n", saved_at,
              whole.steps, same ? "the same bits" : "DIFFERENT", undisturbed ? "changed nothing" : "CHANGED THE RUN",
              whole.history.back().tangential_force, resumed.history.back().tangential_force,
              plain.history.back().tangential_force, mpi::size());
  return same && undisturbed && saved_at > 0;
}

// --- The sliding cells and the oxidized asperity resumed on P ranks ---------------

using test_support::Capture;

// The snapshot of the particles at each sample (positions, velocities, spins,
// images: what a dump writes and more), as a hash of their bits by step.
using Snapshots = std::map<long, std::uint64_t>;
std::uint64_t hash_bytes(std::uint64_t h, const void* data, std::size_t n) {
  const auto* b = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < n; ++k) h = (h ^ b[k]) * 1099511628211ULL;  // FNV-1a
  return h;
}
std::uint64_t snapshot(const Particles& p) {
  std::uint64_t h = 14695981039346656037ULL;
  h = hash_bytes(h, p.position.data(), p.position.size() * sizeof(p.position[0]));
  h = hash_bytes(h, p.velocity.data(), p.velocity.size() * sizeof(p.velocity[0]));
  h = hash_bytes(h, p.omega.data(), p.omega.size() * sizeof(p.omega[0]));
  return hash_bytes(h, p.image.data(), p.image.size() * sizeof(p.image[0]));
}

// The resumed run's snapshots are those of the run that never stopped, at the
// same steps (it takes fewer: those after the state's step).
bool same_snapshots(const Snapshots& whole, const Snapshots& resumed) {
  if (resumed.empty()) return false;
  for (const auto& [step, h] : resumed) {
    const auto at = whole.find(step);
    if (at == whole.end() || at->second != h) return false;
  }
  return true;
}

template <class Sample>
bool same_bits(const std::vector<Sample>& a, const std::vector<Sample>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Sample)) == 0;
}

bool report(const char* study, double at, bool history, bool results, bool snapshots, std::size_t resumed_snapshots,
            double last_whole, double last_resumed) {
  std::printf("%s resumed %.2g of the way on %d rank(s): history %s, results %s, snapshots %s (%zu compared); "
              "last F_T %.17g / %.17g\n",
              study, at, mpi::size(), history ? "the same bits" : "DIFFERENT", results ? "the same" : "DIFFERENT",
              snapshots ? "the same bits" : "DIFFERENT", resumed_snapshots, last_whole, last_resumed);
  return history && results && snapshots;
}

SlidingCellSpec coarse_cell(double d0) {
  SlidingCellSpec c;
  c.material = cohesive_material(materials::silica(), 0.5);
  c.d0 = d0;
  c.velocity = 100.0;
  c.pressure = 0.5e9;
  c.sliding_distance = 2 * d0;
  c.settle_distance = 0.5 * d0;
  c.engine = "lammps";
  return c;
}

constexpr double coarse_d0 = 6e-9;  // a few hundred particles

// Sheared rough surfaces (§7.2), resumed mid-slide and in the rigid-fit window (the last fifth).
bool resume_rough_shear() {
  RoughShearSpec s;
  s.cell = coarse_cell(coarse_d0);
  s.cell.box = {10 * coarse_d0, 3.5 * coarse_d0, 10 * coarse_d0};
  s.roughness = 0.04;
  Capture capture;
  Snapshots whole_snapshots;
  const auto whole = run_rough_shear(
      s, [&](const SlidingCell& c, const SlidingSample&, long step, long) { whole_snapshots[step] = snapshot(c.engine().particles()); },
      capture.hooks());
  if (capture.states.size() < 3) return false;
  bool ok = true;
  for (const double at : {0.5, 1.0}) {
    Snapshots snapshots;
    const auto r = run_rough_shear(
        s, [&](const SlidingCell& c, const SlidingSample&, long step, long) { snapshots[step] = snapshot(c.engine().particles()); },
        capture.resume(at));
    const bool results = r.peak_tangential_force == whole.peak_tangential_force && r.friction == whole.friction &&
                         r.worn == whole.worn && r.wear_particle == whole.wear_particle &&
                         r.wear_particle_residual == whole.wear_particle_residual && r.regime == whole.regime;
    ok &= report("rough shear", at, same_bits(r.history, whole.history), results,
                 same_snapshots(whole_snapshots, snapshots), snapshots.size(), whole.history.back().tangential_force,
                 r.history.back().tangential_force);
  }
  return ok;
}

// Two particles of 3.5 d0 trapped between the surfaces (§7.3), resumed half way.
bool resume_trapped() {
  TrappedParticlesSpec s;
  s.cell = coarse_cell(coarse_d0);
  s.count = 2;
  s.diameter = 3.5 * coarse_d0;
  s.cell.box = {2 * 3 * s.diameter, 3.5 * coarse_d0, s.diameter + 9 * coarse_d0};
  Capture capture;
  Snapshots whole_snapshots, snapshots;
  const auto whole = run_trapped_particles(
      s, [&](const SlidingCell& c, const SlidingSample&, long step, long) { whole_snapshots[step] = snapshot(c.engine().particles()); },
      capture.hooks());
  if (capture.states.size() < 3) return false;
  const auto r = run_trapped_particles(
      s, [&](const SlidingCell& c, const SlidingSample&, long step, long) { snapshots[step] = snapshot(c.engine().particles()); },
      capture.resume(0.5));
  const bool results = r.loose_residual == whole.loose_residual && r.friction == whole.friction &&
                       r.worn_first_body == whole.worn_first_body && r.band_thickness == whole.band_thickness &&
                       r.peak_tangential_force == whole.peak_tangential_force;
  return report("trapped particles", 0.5, same_bits(r.history, whole.history), results,
                same_snapshots(whole_snapshots, snapshots), snapshots.size(), whole.history.back().tangential_force,
                r.history.back().tangential_force);
}

// The oxidized asperity (§9.3.3, reduced to d0 = 6 nm), resumed while sliding.
bool resume_oxide() {
  auto s = test_support::reduced_oxide_asperity(coarse_d0);
  s.engine = "lammps";
  Capture capture;
  Snapshots whole_snapshots, snapshots;
  const auto whole = run_oxide_asperity(
      s, [&](const Engine& e, const OxideAsperitySample&, long step, long, const std::vector<double>&) { whole_snapshots[step] = snapshot(e.particles()); },
      capture.hooks());
  if (capture.states.size() < 5) return false;
  const auto r = run_oxide_asperity(
      s, [&](const Engine& e, const OxideAsperitySample&, long step, long, const std::vector<double>&) { snapshots[step] = snapshot(e.particles()); },
      capture.resume(0.7));
  const bool results = r.rotation == whole.rotation && r.travel == whole.travel && r.final_body == whole.final_body &&
                       r.friction == whole.friction && r.reached_substrate_at == whole.reached_substrate_at &&
                       r.trench_depth == whole.trench_depth;
  return report("oxide asperity", 0.7, same_bits(r.history, whole.history), results,
                same_snapshots(whole_snapshots, snapshots), snapshots.size(), whole.history.back().tangential_force,
                r.history.back().tangential_force);
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  register_lammps_engine();
  if (argc != 2) {
    std::fprintf(stderr, "usage: mpi_dem_lammps patch|junction-kept|junction-touching|rough-shear|resume|"
                         "resume-rough-shear|resume-trapped|resume-oxide\n");
    return 2;
  }
  if (mpi::rank() != 0) {
    serve_lammps_engines();
    return 0;
  }
  bool ok = false;
  {
    const LammpsServedRun served;
    const std::string what = argv[1];
    if (what == "patch") ok = patch();
    else if (what == "junction-kept") ok = junction(false);
    else if (what == "junction-touching") ok = junction(true);
    else if (what == "rough-shear") ok = rough_shear();
    else if (what == "resume") ok = resume();
    else if (what == "resume-rough-shear") ok = resume_rough_shear();
    else if (what == "resume-trapped") ok = resume_trapped();
    else if (what == "resume-oxide") ok = resume_oxide();
    else std::fprintf(stderr, "unknown case %s\n", argv[1]);
  }
  return ok ? 0 : 1;
}
