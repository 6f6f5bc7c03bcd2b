// Reading measured topographies and filling their missing points:
//   build/bench/bench_topography
// Filling: harmonic (Laplace) interpolation of round holes covering ~10 % of
// an n × n measurement, one sparse LDLT per call. Reading: a Gwyddion Simple
// Field and an SDF file of n × n points parsed from memory.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "wearscale/bem/harmonic_fill.hpp"
#include "wearscale/io/topography_io.hpp"

using namespace wearscale;

namespace {

// Holes of radius n/32 on a regular lattice: about 10 % of the points.
std::vector<std::uint8_t> holes(const Grid2D& g) {
  std::vector<std::uint8_t> m(g.size(), 0);
  const double r = static_cast<double>(g.nx) / 32.0, pitch = 5.6 * r;
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const double x = std::fmod(static_cast<double>(i), pitch) - pitch / 2, y = std::fmod(static_cast<double>(j), pitch) - pitch / 2;
      m[g.index(i, j)] = x * x + y * y < r * r ? 1 : 0;
    }
  return m;
}

void BM_HarmonicFill(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const Grid2D g(n, n, 1e-3, 1e-3);
  RealField h(g);
  for (std::size_t k = 0; k < h.size(); ++k) h[k] = std::sin(0.01 * static_cast<double>(k));
  const auto missing = holes(g);
  std::size_t filled = 0;
  for (auto _ : state) {
    RealField work = h;
    filled = bem::harmonic_fill(work, missing);
    benchmark::DoNotOptimize(work.data());
  }
  state.counters["missing"] = static_cast<double>(filled);
  state.counters["points/s"] = benchmark::Counter(static_cast<double>(filled), benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_HarmonicFill)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond);

void BM_ReadGsf(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::string file = fmt::format("Gwyddion Simple Field 1.0\nXRes = {}\nYRes = {}\nXReal = 1e-3\nYReal = 1e-3\nXYUnits = m\nZUnits = m\n", n, n);
  file += std::string(4 - file.size() % 4, '\0');
  for (std::size_t k = 0; k < n * n; ++k) {
    const float v = std::sin(0.01f * static_cast<float>(k)) * 1e-6f;
    char raw[4];
    std::memcpy(raw, &v, 4);
    file.append(raw, 4);
  }
  for (auto _ : state) benchmark::DoNotOptimize(bem::parse_measured_topography(file, "bench.gsf").heights.data());
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * file.size()));
}
BENCHMARK(BM_ReadGsf)->Arg(1024)->Unit(benchmark::kMillisecond);

void BM_ReadSdfAscii(benchmark::State& state) {
  const auto n = static_cast<std::size_t>(state.range(0));
  std::string file = fmt::format("aISO-1.0\nNumPoints = {}\nNumProfiles = {}\nXscale = 1e-6\nYscale = 1e-6\n"
                                 "Zscale = 1e-9\nDataType = 7\n*\n", n, n);
  for (std::size_t k = 0; k < n * n; ++k) file += fmt::format(" {:.6f}", 100.0 * std::sin(0.01 * static_cast<double>(k)));
  for (auto _ : state) benchmark::DoNotOptimize(bem::parse_measured_topography(file, "bench.sdf").heights.data());
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations() * file.size()));
}
BENCHMARK(BM_ReadSdfAscii)->Arg(1024)->Unit(benchmark::kMillisecond);

}  // namespace

// ParaView's view of a field (an HDF5 virtual dataset, one mapping per row)
// against writing the field alone: n × n doubles, compressed as wearscale writes them.
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/xdmf.hpp"

namespace {
void write_field(benchmark::State& state, bool view) {
  const auto n = static_cast<std::size_t>(state.range(0));
  RealField f(Grid2D(n, n, 1e-3, 1e-3));
  for (std::size_t k = 0; k < f.size(); ++k) f[k] = std::sin(0.001 * static_cast<double>(k));
  const auto path = std::filesystem::temp_directory_path() / "bench_xdmf_view.h5";
  for (auto _ : state) {
    H5Writer h5(path);
    h5.write_field("/fields/p", f);
    if (view) XdmfSidecar(f.grid()).add(h5, {{"/fields/p", "p"}});
    h5.commit();
  }
  state.counters["file_MB"] = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
  std::filesystem::remove(path);
}
void BM_WriteField(benchmark::State& state) { write_field(state, false); }
void BM_WriteFieldAndItsXdmfView(benchmark::State& state) { write_field(state, true); }
BENCHMARK(BM_WriteField)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_WriteFieldAndItsXdmfView)->Arg(1024)->Arg(4096)->Unit(benchmark::kMillisecond);
}  // namespace
