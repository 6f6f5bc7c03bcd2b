// DEM throughput on the reference work of bench/dem (README there): the
// dense HCP block with the linear spring-dashpot law with history, and the
// same block with the thesis' cohesive law. Reports particle-steps per
// CPU-second and per wall-second (and as items/s), the neighbour pairs, the
// peak resident set (of the whole process so far: run one benchmark per
// process for a size's own figure) and it per particle, whole and above what
// the process held when it started (its code and libraries, about 4 MiB). On threads also the
// CPU time of the busiest thread (the main one, which runs the serial parts):
// particle-steps per second of it are what the wall clock would show if each
// thread had a core of its own and never waited at a barrier — an upper bound
// of the speed on a quiet machine that a loaded one can still measure, and
// the CPU time of all threads over it shows the serial part and imbalance
// (2 for none on two threads).
//
// NeighborBuild and NeighborBuildAmorphous time the neighbour list's
// rebuild alone (ms per build), on the block and on a random polydisperse
// arrangement.
//
//   OMP_NUM_THREADS=1 build/bench/bench_dem --benchmark_filter=Hooke
//   OMP_NUM_THREADS=2 build/bench/bench_dem --benchmark_filter=Hooke/20
//   OMP_NUM_THREADS=1 build/bench/bench_dem --benchmark_filter=NeighborBuild
// Waiting threads spin briefly, then sleep, as in the CLI (thread_waiting.hpp;
// the context line "threads_wait" says what was in force): on cores shared
// with other jobs a waiting thread then does not take the core the other one
// needs; OMP_WAIT_POLICY or GOMP_SPINCOUNT override it (docs/dem.md, Speed).
#include <algorithm>
#include <benchmark/benchmark.h>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <numbers>
#include <omp.h>
#include <random>
#include <string>
#include <sys/resource.h>
#include <vector>

#include "wearscale/core/thread_waiting.hpp"
#include "wearscale/dem/amorphous_sample.hpp"
#include "wearscale/dem/anchor_block.hpp"
#include "wearscale/dem/cell_order.hpp"
#include "wearscale/dem/hcp_lattice.hpp"

using namespace wearscale::dem;

namespace {

double cpu_seconds() { return static_cast<double>(std::clock()) / CLOCKS_PER_SEC; }

// A field of /proc/self/status in MiB ("VmHWM:" the peak resident set, "VmRSS:" the current one).
double status_mib(const std::string& field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind(field, 0) == 0) return std::stod(line.substr(field.size())) / 1024.0;
  return 0.0;
}
double peak_rss_mib() { return status_mib("VmHWM:"); }
// What the process holds before any system is built (code, libraries, the
// runtime's heaps): not per particle.
const double start_rss_mib = status_mib("VmRSS:");
// How the threads wait, in the run's context lines.
const bool waiting_shown = (benchmark::AddCustomContext("threads_wait", wearscale::thread_waiting()), true);

// CPU seconds so far of each thread of the OpenMP team (the same threads
// run every parallel region of the same size).
std::vector<double> thread_cpu_seconds() {
  std::vector<double> out(static_cast<std::size_t>(omp_get_max_threads()), 0.0);
#pragma omp parallel
  {
    rusage u{};
    getrusage(RUSAGE_THREAD, &u);
    out[static_cast<std::size_t>(omp_get_thread_num())] =
        static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
  }
  return out;
}

void report(benchmark::State& state, const Simulation& sim, long steps, double cpu, double wall, double busiest) {
  const double work = static_cast<double>(sim.particles().size()) * static_cast<double>(steps);
  state.SetItemsProcessed(static_cast<std::int64_t>(work));
  state.counters["N"] = static_cast<double>(sim.particles().size());
  state.counters["pairs"] = static_cast<double>(sim.neighbor_list().pairs());
  state.counters["Mpsteps_per_cpu_s"] = work / cpu / 1e6;
  state.counters["Mpsteps_per_wall_s"] = work / wall / 1e6;
  state.counters["Mpsteps_per_busiest_thread_cpu_s"] = work / busiest / 1e6;
  state.counters["cpu_over_busiest_thread"] = cpu / busiest;
  state.counters["peak_RSS_MiB"] = peak_rss_mib();
  state.counters["peak_RSS_B_per_particle"] = peak_rss_mib() * 1048576.0 / static_cast<double>(sim.particles().size());
  state.counters["peak_RSS_above_start_B_per_particle"] =
      (peak_rss_mib() - start_rss_mib) * 1048576.0 / static_cast<double>(sim.particles().size());
}

// Runs state.range(1) steps per iteration after a warm-up (first build,
// warm caches) and reports them.
void time_steps(benchmark::State& state, Simulation& sim) {
  const long steps = state.range(1);
  sim.run(10);
  double cpu = 0.0, wall = 0.0;
  long done = 0;
  std::vector<double> per_thread(static_cast<std::size_t>(omp_get_max_threads()), 0.0);
  for (auto _ : state) {
    const auto t0 = thread_cpu_seconds();
    const double c0 = cpu_seconds();
    const auto w0 = std::chrono::steady_clock::now();
    sim.run(steps);
    wall += std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    cpu += cpu_seconds() - c0;
    const auto t1 = thread_cpu_seconds();
    for (std::size_t t = 0; t < per_thread.size(); ++t) per_thread[t] += t1[t] - t0[t];
    done += steps;
  }
  report(state, sim, done, cpu, wall, *std::max_element(per_thread.begin(), per_thread.end()));
}

// The deck's block: N = 4 n³, rebuild every 10 steps without a check.
void Hooke(benchmark::State& state) {
  auto sim = make_anchor_block({static_cast<int>(state.range(0)), 10});
  time_steps(state, sim);
}
BENCHMARK(Hooke)->Args({20, 200})->Args({40, 50})->Unit(benchmark::kMillisecond)->UseRealTime();

// The same block renumbered in cell order at every state.range(2)-th build
// (NeighborSettings::renumber_every; Hooke: never).
void HookeSorted(benchmark::State& state) {
  auto sim = make_anchor_block({static_cast<int>(state.range(0)), 10, static_cast<int>(state.range(2))});
  time_steps(state, sim);
}
BENCHMARK(HookeSorted)->Args({20, 200, 1})->Args({20, 200, 10})->Args({40, 50, 10})->Unit(benchmark::kMillisecond)->UseRealTime();

// The thesis law on the same block: unit spheres of a cohesive material whose
// d_c is above the particle size, neighbours at 0.5 % overlap. Numbered as
// the lattice is built (`Cohesive`), shuffled as a randomly inserted sample
// would be (`CohesiveShuffled`), or shuffled and then numbered along the
// cells (`CohesiveRenumbered`, cell_order.hpp): the same work, in three orders.
enum class Numbering { Lattice, Shuffled, Renumbered };
void cohesive_block(benchmark::State& state, Numbering numbering) {
  const int n = static_cast<int>(state.range(0));
  HcpLattice lattice{0.995, n, n, n};
  CohesiveMaterial m;
  m.name = "bench";
  m.young = 1e4;
  m.poisson = 0.15;
  m.tensile_strength = 100.0;
  m.shear_strength = 50.0;
  m.surface_energy = 2.5;  // d_min = 0.1 (δ_f = 0.1 d), d_c = 10 d
  m.restitution = 0.9;
  m.density = 6.0 / std::numbers::pi;
  Particles p;
  for (const auto& x : lattice.sites()) {
    const double h = std::sin(12.9898 * x.x + 78.2330 * x.y + 37.7190 * x.z) * 43758.5453;
    p.add({x, 0.5, m.density, {0.01 * (2.0 * (h - std::floor(h)) - 1.0), 0, 0}, 0, 0});
  }
  if (numbering != Numbering::Lattice) {
    std::vector<std::size_t> order(p.size());
    for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
    std::shuffle(order.begin(), order.end(), std::mt19937_64(1));
    p.reorder(order);
  }
  if (numbering == Numbering::Renumbered) p.reorder(cell_order(p.position, 0.6));
  Simulation sim(std::move(p), lattice.box(), CohesiveLaw({m}), NeighborSettings{0.1, 10, false});
  sim.set_time_step(0.1 * sim.law_as<CohesiveLaw>().critical_time_step(sim.particles()));
  time_steps(state, sim);
}
void Cohesive(benchmark::State& state) { cohesive_block(state, Numbering::Lattice); }
void CohesiveShuffled(benchmark::State& state) { cohesive_block(state, Numbering::Shuffled); }
void CohesiveRenumbered(benchmark::State& state) { cohesive_block(state, Numbering::Renumbered); }
BENCHMARK(Cohesive)->Args({20, 200})->Args({40, 50})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(CohesiveShuffled)->Args({40, 50})->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(CohesiveRenumbered)->Args({40, 50})->Unit(benchmark::kMillisecond)->UseRealTime();

// The neighbour list's rebuild alone, on the deck's block after 10 steps:
// the cell grid, the search, the rows' sort and the histories carried over
// (the positions do not move between builds, so every history is carried).
// The time is per build; `pairs` the list's.
void NeighborBuild(benchmark::State& state) {
  auto sim = make_anchor_block({static_cast<int>(state.range(0)), 10});
  sim.run(10);
  const Particles p = sim.particles();
  NeighborList list;
  const double skin = 0.1;  // the deck's, d = 1
  list.build(p, sim.box(), sim.reach(), skin, sim.law().history_size());
  for (auto _ : state) list.build(p, sim.box(), sim.reach(), skin, sim.law().history_size());
  state.counters["N"] = static_cast<double>(p.size());
  state.counters["pairs"] = static_cast<double>(list.pairs());
}
BENCHMARK(NeighborBuild)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond)->UseRealTime();

// The same on an amorphous arrangement (§6.2.2's sizes 0.75-1.25 d0, placed
// at random to a volume fraction of 0.75 and numbered along the cells, as the
// carved SiO2 of the oxide study is), about 4 n³ particles; skin 0.1 d0,
// contact only. Its candidates pass the distance test in no pattern a
// branch predictor learns, unlike the lattice's.
void NeighborBuildAmorphous(benchmark::State& state) {
  const double n = static_cast<double>(state.range(0));
  AmorphousSpec spec;
  spec.box_size = {1.434 * n, 1.434 * n, 1.434 * n};  // about 4 n³ particles (0.75 of the volume, ≈ 0.55 d0³ each)
  Particles p = insert_randomly(spec, 1.0);
  p.reorder(cell_order(p.position, 0.5 * spec.sizes.largest));
  const Box box = periodic_box(spec.box_size);
  NeighborList list;
  const double skin = 0.1;
  list.build(p, box, 0.0, skin, 3);
  for (auto _ : state) list.build(p, box, 0.0, skin, 3);
  state.counters["N"] = static_cast<double>(p.size());
  state.counters["pairs"] = static_cast<double>(list.pairs());
}
BENCHMARK(NeighborBuildAmorphous)->Arg(20)->Arg(40)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
