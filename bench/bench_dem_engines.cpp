// The two DEM engines on the same work, one run per process: particle-steps
// per CPU-second (all ranks' CPU) and per wall-second, and the peak resident
// set of each rank. Under `mpirun -np P` the LAMMPS engine spreads the run
// over the P ranks (rank 0 builds the system and drives it, the others serve
// it); the wearscale engine runs on rank 0 alone.
//
//   bench_dem_engines anchor   wearscale|lammps [n=20] [steps=1000]   the deck of bench/dem (Hooke, 4 n³ spheres)
//   bench_dem_engines junction wearscale|lammps [scale=1] [slide=0.2] the §7.1.1 cell at D = L, p_N = 0, 10 m/s,
//                                                                     its length, height and depth × scale
//   bench_dem_engines oxide    wearscale|lammps [d0=6e-9] [slide=3e-9] [record_every=200]
//                                                                     Fig. 9.26's cell (the case's geometry, 95 nm
//                                                                     high, 50 m/s): timed from its first sample
//                                                                     (the SiO2's relaxation, rank 0's, before)
//   mpirun -np 2 build/bench/bench_dem_engines junction lammps 3
//
// The timed part is the run alone (the sample is built before the clocks
// start); one line of results on rank 0, with the load average beside it.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include <mpi.h>

#include "wearscale/core/mpi.hpp"
#include "wearscale/dem/anchor_block.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/junction_strength.hpp"
#include "wearscale/dem/lammps_engine.hpp"
#include "wearscale/dem/oxide_asperity.hpp"
#include "wearscale/materials/material.hpp"

using namespace wearscale;
using namespace wearscale::dem;

namespace {

double cpu_seconds() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
         1e-6 * static_cast<double>(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

double peak_rss_mib() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;
  return 0.0;
}

std::string load_average() {
  std::ifstream in("/proc/loadavg");
  std::string one;
  in >> one;
  return one;
}

struct Work {
  std::size_t particles = 0;
  long steps = 0;
  double cpu = 0.0;  ///< rank 0's CPU seconds over the timed run
};

// The deck's block (anchor_block.hpp) on an engine: the same particles, law,
// walls and rebuilds every 10 steps.
Work anchor(const std::string& engine, int n, long steps, double& wall) {
  Simulation made = make_anchor_block({n, 10});
  std::vector<std::vector<std::size_t>> members;
  for (std::size_t w = 0; w < made.wall_count(); ++w) members.push_back(made.wall(static_cast<int>(w)).members);
  Particles p = made.particles();
  for (std::size_t i = 0; i < p.size(); ++i) p.wall[i] = no_wall;
  auto e = make_engine(engine, {std::move(p), made.box(), made.law().clone(), NeighborSettings{0.1, 10, false}});
  for (auto& m : members) e->add_wall(std::move(m), WallMotion::fixed());
  e->set_time_step(made.time_step());
  e->run(10);  // the first build, warm caches
  const double c0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  e->run(steps);
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - c0;
  std::printf("# kinetic energy after %ld steps: %.10g\n", steps + 10, e->kinetic_energy());
  return {e->particles().size(), steps, cpu};
}

// The full-contact cell of Fig. 7.2 slid at 10 m/s (the junction driver,
// its samples every 200 steps included).
Work junction(const std::string& engine, int scale, double slide, double& wall) {
  JunctionStrengthSpec s;
  s.top = s.bottom = cohesive_material(materials::silica(), 0.5);
  s.cell.d0 = 1.5e-9;
  s.cell.length = 25 * scale;
  s.cell.height = 14 * scale;
  s.cell.depth = scale;
  s.contact_ratio = 1.0;
  s.settle_distance = 0.0;
  s.sliding_distance = slide;
  s.engine = engine;
  const double c0 = cpu_seconds();
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = run_junction_strength(s);
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - c0;
  std::printf("# peak p_T %.4f GPa over %.3g nm\n", r.peak_tangential / 1e9, slide * r.length * 1e9);
  return {r.particles, r.steps, cpu};
}

// The oxidized asperity of Fig. 9.26 (the case's geometry 95 nm high, the
// 0.5 J/m² interface, 50 m/s), timed from its first sample: what the
// engine and the driver's samples (body tracking, trench) cost per step.
Work oxide(const std::string& engine, double d0, double slide, long record_every, double& wall) {
  OxideAsperitySpec s;
  s.oxide = cohesive_material(materials::silica(), 0.5);
  s.substrate = cohesive_material(materials::silicon(), 0.5, 0.9);
  s.substrate.poisson = 0.2;
  CohesiveMaterial interface = mix(s.oxide, s.substrate);
  interface.surface_energy = 0.5;
  s.interface = interface;
  s.d0 = d0;
  s.box = {150e-9, 150e-9, 95e-9};
  s.velocity = 50.0;
  s.sliding_distance = slide;
  s.settle_distance = 1e-9;
  s.record_every = record_every;
  s.engine = engine;
  double c0 = 0.0;
  long first = 0;
  std::chrono::steady_clock::time_point t0;
  const auto r = run_oxide_asperity(s, [&](const Engine&, const OxideAsperitySample&, long step, long, const std::vector<double>&) {
    if (first == 0) {
      first = step;
      c0 = cpu_seconds();
      t0 = std::chrono::steady_clock::now();
    }
  });
  wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - c0;
  std::printf("# %zu particles (%zu in the cylinder), %ld steps timed of %ld, rolling ratio %.3f\n", r.particles,
              r.body_particles, r.steps - first, r.steps, r.rolling_ratio);
  return {r.particles, r.steps - first, cpu};
}

}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  register_lammps_engine();
  if (argc < 3) {
    std::fprintf(stderr, "usage: bench_dem_engines anchor|junction wearscale|lammps [size] [steps|slide]\n");
    return 2;
  }
  const std::string what = argv[1], engine = argv[2];
  int ranks = 1, rank = 0;
  const bool parallel = mpi::active();
  if (parallel) {
    MPI_Comm_size(MPI_COMM_WORLD, &ranks);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  }
  const double cpu0 = cpu_seconds();
  Work work;
  double wall = 0.0;
  if (rank != 0) {
    serve_lammps_engines();
  } else {
    const LammpsServedRun served;
    if (what == "anchor")
      work = anchor(engine, argc > 3 ? std::atoi(argv[3]) : 20, argc > 4 ? std::atol(argv[4]) : 1000, wall);
    else if (what == "oxide")
      work = oxide(engine, argc > 3 ? std::atof(argv[3]) : 6e-9, argc > 4 ? std::atof(argv[4]) : 3e-9,
                   argc > 5 ? std::atol(argv[5]) : 200, wall);
    else
      work = junction(engine, argc > 3 ? std::atoi(argv[3]) : 1, argc > 4 ? std::atof(argv[4]) : 0.2, wall);
  }
  // CPU: rank 0's over the timed run, the others' all along (they wait
  // without spinning while rank 0 builds); the peak resident set of each.
  double cpu = rank == 0 ? work.cpu : cpu_seconds() - cpu0, rss = peak_rss_mib();
  double cpu_all = cpu, rss_max = rss, rss_sum = rss;
  if (parallel) {
    MPI_Reduce(&cpu, &cpu_all, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    MPI_Reduce(&rss, &rss_max, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
    MPI_Reduce(&rss, &rss_sum, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  }
  if (rank == 0) {
    const double ps = static_cast<double>(work.particles) * static_cast<double>(work.steps);
    std::printf("%s %s ranks=%d particles=%zu steps=%ld wall=%.2f s cpu=%.2f s  %.3g M particle-steps per CPU-s  "
                "%.3g M per wall-s  peak RSS %.1f MiB max a rank (%.0f B a particle, all ranks)  load %s\n",
                what.c_str(), engine.c_str(), ranks, work.particles, work.steps, wall, cpu_all, ps / cpu_all / 1e6,
                ps / wall / 1e6, rss_max, rss_sum * 1048576.0 / static_cast<double>(work.particles),
                load_average().c_str());
  }
  return 0;
}
