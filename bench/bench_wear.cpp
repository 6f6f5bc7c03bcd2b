// The numerical detachment model of ch. 5 on rough micro-contact maps
// (H = 0.8, q_l = 8, q_s = n/8, p̃_N = 0.1, d*/L = 0.05): the energy release
// (5.3) of one candidate by the fast evaluator (a sum of u over C plus the
// self-energy, cached per candidate — first use and reuse timed apart) against
// one full padded-FFT solve per candidate (the naive baseline), and one map
// pixel (the whole §5.1 procedure) fast and naive.
//
//   OMP_NUM_THREADS=1 build/bench/bench_wear --benchmark_filter=Release
//   OMP_NUM_THREADS=2 build/bench/bench_wear --benchmark_filter=Pixel/128
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "wearscale/wear/detachment.hpp"

using namespace wearscale;
using namespace wearscale::wear;

namespace {

constexpr double kNu = 0.3, kLoad = 0.1, kDstar = 0.05;

const DetachmentModel& model(std::size_t n) {
  static std::map<std::size_t, std::unique_ptr<DetachmentModel>> cache;
  auto& m = cache[n];
  if (!m) {
    RoughContactSpec spec;
    spec.n = n;
    spec.k_s = static_cast<double>(n) / 8.0;
    RoughContactSeries series(spec, 1);
    m = std::make_unique<DetachmentModel>(series.at_load(kLoad),
                                          ShearedJunctions{1.0, 1.0 / (2.0 * (1.0 + kNu)), kNu, 1.0, 0.05});
  }
  return *m;
}

// ΔE of every candidate in turn: the sum of u over C (prefix sums) plus the self-energy (not cached here).
void BM_ReleaseFast(benchmark::State& state) {
  const auto& m = model(static_cast<std::size_t>(state.range(0)));
  const Grid2D& g = m.map().grid;
  DiscSums work(g);
  work.build(m.map().contact, &m.displacement());
  std::size_t c = 0;
  const auto& cands = m.candidates();
  for (auto _ : state) {
    const Disc& d = cands[c++ % cands.size()];
    benchmark::DoNotOptimize(
        EnergyRelease::release(g.cell_area() * work.sum(d), m.energy_release().self_energy(d, m.map().contact)));
  }
  state.counters["candidates"] = static_cast<double>(cands.size());
}

// The same with the self-energy known (every later pass and every other d*): the sum of u over C only.
void BM_ReleaseFastCached(benchmark::State& state) {
  const auto& m = model(static_cast<std::size_t>(state.range(0)));
  const Grid2D& g = m.map().grid;
  DiscSums work(g);
  work.build(m.map().contact, &m.displacement());
  std::size_t c = 0;
  const auto& cands = m.candidates();
  for (auto _ : state) benchmark::DoNotOptimize(work.sum(cands[c++ % cands.size()]));
}

// One full solve of p − p_C per candidate.
void BM_ReleaseNaive(benchmark::State& state) {
  const auto& m = model(static_cast<std::size_t>(state.range(0)));
  const Grid2D& g = m.map().grid;
  RealField p(g), u(g);
  auto w = m.energy_release().compliance().workspace();
  std::size_t c = 0;
  const auto& cands = m.candidates();
  for (auto _ : state)
    benchmark::DoNotOptimize(
        m.energy_release().naive_release(cands[c++ % cands.size()], m.map().contact, m.elastic_energy(), p, u, w));
}

void BM_PixelFast(benchmark::State& state) {
  const auto& m = model(static_cast<std::size_t>(state.range(0)));
  std::size_t particles = 0;
  for (auto _ : state) particles = m.detach(kDstar).particles.size();
  state.counters["particles"] = static_cast<double>(particles);
}

void BM_PixelNaive(benchmark::State& state) {
  const auto& m = model(static_cast<std::size_t>(state.range(0)));
  DetachmentOptions opt;
  opt.method = EnergyReleaseMethod::Naive;
  std::size_t particles = 0, solves = 0;
  for (auto _ : state) {
    const auto r = m.detach(kDstar, opt);
    particles = r.particles.size();
    solves = r.solves;
  }
  state.counters["particles"] = static_cast<double>(particles);
  state.counters["solves"] = static_cast<double>(solves);
}

}  // namespace

BENCHMARK(BM_ReleaseFast)->Arg(128)->Arg(512)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReleaseFastCached)->Arg(128)->Arg(512)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_ReleaseNaive)->Arg(128)->Arg(512)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PixelFast)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PixelNaive)->Arg(128)->Unit(benchmark::kMillisecond)->Iterations(1);
