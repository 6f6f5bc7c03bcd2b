// What an OpenMP parallel region and a barrier cost on this machine, the
// figures behind the programs' choice of how waiting threads wait
// (core/include/wearscale/core/thread_waiting.hpp, bench/results/dem.md, "waiting threads chosen by the program").
// Each benchmark times one region (or barrier) over 2000 doubles, which is
// next to no work: the time is the waking and joining of the team.
//   OMP_NUM_THREADS=2 build/bench/bench_threads                    # as the programs set it
//   OMP_NUM_THREADS=2 OMP_WAIT_POLICY=passive build/bench/bench_threads
//   OMP_NUM_THREADS=2 GOMP_SPINCOUNT=300000 build/bench/bench_threads
// The context line "threads_wait" says what was in force.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <vector>

#include "wearscale/core/thread_waiting.hpp"

namespace {

const bool waiting_shown = (benchmark::AddCustomContext("threads_wait", wearscale::thread_waiting()), true);

std::vector<double> values(2000, 1.0);

double region(double scale) {
  double sum = 0.0;
  const auto n = static_cast<long>(values.size());
#pragma omp parallel for reduction(+ : sum) schedule(static)
  for (long i = 0; i < n; ++i) sum += scale * values[static_cast<std::size_t>(i)];
  return sum;
}

// A parallel region right after the last one: what a time step pays for each.
void BM_ParallelRegion(benchmark::State& state) {
  double k = 0.0;
  for (auto _ : state) benchmark::DoNotOptimize(region(k += 1.0));
  state.counters["threads"] = omp_get_max_threads();
}
BENCHMARK(BM_ParallelRegion)->UseRealTime();

// Ten loops in one region, each ended by its barrier: the time per barrier.
void BM_Barrier(benchmark::State& state) {
  double sum = 0.0;
  const auto n = static_cast<long>(values.size());
  for (auto _ : state) {
#pragma omp parallel
    for (int b = 0; b < 10; ++b) {
#pragma omp for reduction(+ : sum) schedule(static)
      for (long i = 0; i < n; ++i) sum += values[static_cast<std::size_t>(i)];
    }
  }
  benchmark::DoNotOptimize(sum);
  state.SetItemsProcessed(state.iterations() * 10);  // items/s: barriers per second
}
BENCHMARK(BM_Barrier)->UseRealTime();

// A region after `us` microseconds of serial work (the other threads have
// waited that long): the serial wait is excluded from the time.
void BM_RegionAfterSerialWork(benchmark::State& state) {
  const auto serial = std::chrono::microseconds(state.range(0));
  double k = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    const auto until = std::chrono::steady_clock::now() + serial;
    while (std::chrono::steady_clock::now() < until) benchmark::DoNotOptimize(k += 1.0);
    state.ResumeTiming();
    benchmark::DoNotOptimize(region(k));
  }
}
BENCHMARK(BM_RegionAfterSerialWork)->Arg(30)->Arg(300)->UseRealTime();

}  // namespace
