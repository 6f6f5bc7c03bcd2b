#include "wearscale/wear/energy_release.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>

#ifdef _OPENMP
#include <omp.h>
#else
inline bool omp_in_parallel() { return false; }
#endif

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

namespace {

std::size_t at(const Grid2D& g, long i, long j) { return g.index(static_cast<std::size_t>(i), static_cast<std::size_t>(j)); }

// FFT sizes 2^k and 3·2^k: few plans, each fast.
std::size_t nice_size(std::size_t m) {
  std::size_t p = 8;
  while (true) {
    if (p >= m) return p;
    if (p * 3 / 2 >= m) return p * 3 / 2;
    p *= 2;
  }
}

// The autocorrelation of a box's mask by FFT: the mask stays 0 but for the
// cells set by one call (cleared again after it), so no call clears m² points.
struct BoxScratch {
  std::shared_ptr<const FFTPlan> plan;
  RealField mask, correlation;
  ComplexField spectrum;
};

BoxScratch& box_scratch(std::size_t m) {
  thread_local std::map<std::size_t, std::unique_ptr<BoxScratch>> cache;
  auto& s = cache[m];
  if (!s) {
    s = std::make_unique<BoxScratch>();
    const Grid2D g(m, m, 1.0, 1.0);
    s->plan = FFTPlanCache::global().plan(g);
    s->mask = RealField(g);
    s->correlation = RealField(g);
    s->spectrum = ComplexField::spectrum_of(g);
  }
  return *s;
}

// Σ_q (hi[q][j] − lo[q][j]) for the j of blocks of W cells from j: one
// accumulator per cell, kept in registers across the pairs of rows.
template <int W>
inline void block_sums(const double* const* hi, const double* const* lo, std::size_t n, long j, double* out) {
  double acc[W] = {};
  for (std::size_t q = 0; q < n; ++q) {
    const double *h = hi[q] + j, *l = lo[q] + j;
#pragma omp simd
    for (int w = 0; w < W; ++w) acc[w] += h[w] - l[w];
  }
  for (int w = 0; w < W; ++w) out[w] = acc[w];
}

// sum[j] = Σ_q (hi[q][j] − lo[q][j]) for the j of each segment, whose bounds
// are multiples of 8. Compiled also for AVX2 and AVX-512, the best one
// chosen at load time.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("avx512f", "avx2", "default")))
#endif
void accumulate_run_sums(const double* const* hi, const double* const* lo, std::size_t n,
                         const std::pair<long, long>* segments, std::size_t n_segments, double* sum) {
  for (std::size_t q = 0; q < n_segments; ++q) {
    long j = segments[q].first;
    const long end = segments[q].second;
    for (; j + 32 <= end; j += 32) block_sums<32>(hi, lo, n, j, sum + j);
    for (; j < end; j += 8) block_sums<8>(hi, lo, n, j, sum + j);
  }
}

}  // namespace

DiscSums::DiscSums(const Grid2D& grid)
    : grid_(grid), prefix_((grid.nx + 1) * grid.ny, 0.0), fresh_((grid.ny + kBlock - 1) / kBlock, 0) {}

void DiscSums::build(const std::vector<std::uint8_t>& mask, const RealField* values) {
  mask_ = &mask;
  values_ = values;
  for (std::size_t b = 0; b < fresh_.size(); ++b) build_block(b);
}

void DiscSums::stale() { std::fill(fresh_.begin(), fresh_.end(), 0); }

void DiscSums::prepare(const Disc& disc) {
  const long r = static_cast<long>(std::floor(disc.radius_cells() + 1e-9));
  const long ny = static_cast<long>(grid_.ny);
  const long first = std::max(0L, disc.j - r), last = std::min(ny - 1, disc.j + r);
  if (last < first) return;
  for (auto b = static_cast<std::size_t>(first) / kBlock; b <= static_cast<std::size_t>(last) / kBlock; ++b)
    if (!fresh_[b]) build_block(b);
}

void DiscSums::build_block(std::size_t block) {
  // prefix_[m ny + j] = Σ_{i < m} mask·value at (i, j) for the rows j of the block.
  const std::size_t nx = grid_.nx, ny = grid_.ny, j0 = block * kBlock, j1 = std::min(ny, j0 + kBlock);
  double* prefix = prefix_.data();
  std::fill(prefix + j0, prefix + j1, 0.0);
  for (std::size_t m = 0; m < nx; ++m) {
    const std::uint8_t* in = mask_->data() + m * ny;
    const double* before = prefix + m * ny;
    double* after = prefix + (m + 1) * ny;
    if (values_) {
      const double* v = values_->data() + m * ny;
#pragma omp simd
      for (std::size_t j = j0; j < j1; ++j) after[j] = before[j] + (in[j] ? v[j] : 0.0);
    } else {
#pragma omp simd
      for (std::size_t j = j0; j < j1; ++j) after[j] = before[j] + (in[j] ? 1.0 : 0.0);
    }
  }
  fresh_[block] = 1;
}

double DiscSums::sum(const Disc& disc) const {
  const std::size_t ny = grid_.ny;
  double s = 0.0;
  disc.for_each_row(grid_, [&](long row, long first, long last) {
    const auto j = static_cast<std::size_t>(row);
    s += prefix_[static_cast<std::size_t>(last + 1) * ny + j] - prefix_[static_cast<std::size_t>(first) * ny + j];
  });
  return s;
}

EnergyRelease::EnergyRelease(const TangentialCompliance& f, double sigma_j) : f_(&f), sigma_j_(sigma_j) {
  if (!(sigma_j > 0.0) || !std::isfinite(sigma_j))
    throw InputError(fmt::format("energy release: junction strength σ_j = {} is not allowed; allowed: > 0", sigma_j));
}

double EnergyRelease::self_energy(const Disc& disc, const std::vector<std::uint8_t>& loaded) const {
  const Grid2D& g = f_->grid();
  // The loaded cells of C.
  thread_local std::vector<std::pair<long, long>> cells;
  cells.clear();
  long i_min = 0, i_max = 0, j_min = 0, j_max = 0;
  bool first_cell = true;
  disc.for_each_row(g, [&](long row, long first, long last) {
    for (long i = first; i <= last; ++i)
      if (loaded[at(g, i, row)]) {
        cells.emplace_back(i, row);
        if (first_cell) {
          i_min = i_max = i;
          j_min = j_max = row;
          first_cell = false;
        }
        i_min = std::min(i_min, i), i_max = std::max(i_max, i);
        j_min = std::min(j_min, row), j_max = std::max(j_max, row);
      }
  });
  if (cells.empty()) return 0.0;
  const double scale = 0.5 * g.cell_area() * sigma_j_ * sigma_j_;
  const std::size_t bx = static_cast<std::size_t>(i_max - i_min + 1), by = static_cast<std::size_t>(j_max - j_min + 1);
  const std::size_t m = nice_size(2 * std::max(bx, by) - 1);
  const double c = static_cast<double>(cells.size());
  // Pairs cost ~2 ns each; an FFT pair of m² points ~ m² log2(m²) ns plus the loop over the (2b)² offsets.
  const double direct_cost = c * c, fft_cost = static_cast<double>(m * m) * std::log2(double(m * m)) + 8.0 * double(bx * by);
  if (direct_cost <= fft_cost) {
    // Σ_{a,b∈C} G(a − b) by pairs (G is even).
    double sum = 0.0;
    const std::size_t n = cells.size();
    for (std::size_t a = 0; a < n; ++a) {
      double row = 0.5 * f_->kernel(0, 0);
      for (std::size_t b = a + 1; b < n; ++b)
        row += f_->kernel(cells[a].first - cells[b].first, cells[a].second - cells[b].second);
      sum += row;
    }
    return 2.0 * scale * sum;
  }
  // Autocorrelation A(r) = #{(a, b) ∈ C²: a − b = r} = IDFT |DFT 1_C|² on an m × m box (m ≥ 2 box − 1: no aliasing).
  BoxScratch& s = box_scratch(m);
  for (const auto& [i, j] : cells) s.mask(static_cast<std::size_t>(i - i_min), static_cast<std::size_t>(j - j_min)) = 1.0;
  s.plan->forward(s.mask, s.spectrum);
  for (const auto& [i, j] : cells) s.mask(static_cast<std::size_t>(i - i_min), static_cast<std::size_t>(j - j_min)) = 0.0;
  for (auto& z : s.spectrum) z = std::norm(z);
  s.plan->backward(s.spectrum, s.correlation);
  double sum = 0.0;
  const long lbx = static_cast<long>(bx), lby = static_cast<long>(by), lm = static_cast<long>(m);
  for (long di = -(lbx - 1); di < lbx; ++di)
    for (long dj = -(lby - 1); dj < lby; ++dj) {
      const double count = std::floor(  // a pair count, ≥ 0, up to round-off
          s.correlation(static_cast<std::size_t>((di + lm) % lm), static_cast<std::size_t>((dj + lm) % lm)) + 0.5);
      if (count != 0.0) sum += count * f_->kernel(di, dj);
    }
  return scale * sum;
}

void EnergyRelease::traction(const std::vector<std::uint8_t>& loaded, RealField& p) const {
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = loaded[k] ? sigma_j_ : 0.0;
}

double EnergyRelease::naive_release(const Disc& disc, const std::vector<std::uint8_t>& loaded, double energy,
                                    RealField& p, RealField& u, TangentialCompliance::Workspace& w) const {
  const Grid2D& g = f_->grid();
  traction(loaded, p);
  disc.for_each_row(g, [&](long row, long first, long last) {
    for (long i = first; i <= last; ++i) p[at(g, i, row)] = 0.0;
  });
  f_->displacement(p, u, w);
  return energy - f_->energy(p, u);  // E(p) − E(p − p_C)
}

// u[k] −= σ_j Σ_{r ∈ removed} G(k − r) on the loaded cells k, the sum over r
// taken in the order of `removed` for every k. The cells of a column i are
// contiguous, so the sums run over segments of loaded cells along j, every
// cell of a segment accumulating its own sum (vectorised across cells): the
// kernel row G(|i − ri|, ·) is read forwards for j ≥ rj and backwards below.
ColumnSegments::ColumnSegments(const Grid2D& g, const std::vector<std::uint8_t>& mask) : first(g.nx + 1, 0) {
  const long ny = static_cast<long>(g.ny), padded = static_cast<long>((g.ny + 7) / 8 * 8);
  constexpr long kGap = 8;  // cells between two runs summed rather than starting a new segment
  for (std::size_t i = 0; i < g.nx; ++i) {
    first[i] = spans.size();
    const std::uint8_t* in = mask.data() + i * g.ny;
    for (long j = 0; j < ny; ++j) {
      if (!in[j]) continue;
      long end = j + 1;
      while (end < ny && in[end]) ++end;
      const long lo = j / 8 * 8, hi = std::min(padded, (end + 7) / 8 * 8);
      if (spans.size() > first[i] && lo - spans.back().second < kGap)
        spans.back().second = hi;
      else
        spans.emplace_back(lo, hi);
      j = end;
    }
  }
  first[g.nx] = spans.size();
  for (const auto& [lo, hi] : spans) cells += static_cast<std::size_t>(hi - lo);
}

// u[k] −= σ_j Σ_{r ∈ removed} G(k − r) on the cells k of the cover (those not
// loaded any more get it too: their u is not read). Each run of removed cells
// along x sums as the difference of two rows of the kernel summed along x
// (TangentialCompliance::cumulative_row): per target column i, one pair of
// rows a run (two for the run that holds column i), summed over blocks of
// cells along j (contiguous in memory).
void EnergyRelease::subtract_run_sums(const std::vector<std::array<long, 3>>& runs, const ColumnSegments& cover,
                                      std::size_t remaining, RealField& u) const {
  const Grid2D& g = f_->grid();
  const long nx = static_cast<long>(g.nx), ny = static_cast<long>(g.ny);
  const long padded = static_cast<long>(f_->padded_ny());
  const double sigma = sigma_j_;
  const auto row = [&](long a, long rj) { return f_->cumulative_row(static_cast<std::size_t>(a)) - rj; };
#pragma omp parallel if (!omp_in_parallel() && remaining > 4096)
  {
    thread_local std::vector<double> s;
    thread_local std::vector<const double*> hi, lo;
    s.resize(static_cast<std::size_t>(padded));
#pragma omp for schedule(static)
    for (long i = 0; i < nx; ++i) {
      const std::size_t s0 = cover.first[static_cast<std::size_t>(i)], s1 = cover.first[static_cast<std::size_t>(i) + 1];
      if (s0 == s1) continue;
      hi.clear(), lo.clear();
      for (const auto& [rj, r0, r1] : runs) {  // Σ_{r0 ≤ ri ≤ r1} G(i − ri, ·), by a = |i − ri|
        if (i >= r1) {
          hi.push_back(row(i - r0 + 1, rj)), lo.push_back(row(i - r1, rj));
        } else if (i <= r0) {
          hi.push_back(row(r1 - i + 1, rj)), lo.push_back(row(r0 - i, rj));
        } else {  // a = 0 … i − r0 and a = 1 … r1 − i
          hi.push_back(row(i - r0 + 1, rj)), lo.push_back(row(0, rj));
          hi.push_back(row(r1 - i + 1, rj)), lo.push_back(row(1, rj));
        }
      }
      double* sum = s.data();
      accumulate_run_sums(hi.data(), lo.data(), hi.size(), cover.spans.data() + s0, s1 - s0, sum);
      double* ui = u.data() + i * ny;
      for (std::size_t q = s0; q < s1; ++q) {
        const long j1 = std::min(cover.spans[q].second, ny);
#pragma omp simd
        for (long j = cover.spans[q].first; j < j1; ++j) ui[j] -= sigma * sum[j];
      }
    }
  }
}

RealField& SolveScratch::traction() {
  if (!p_) p_.emplace(f_->grid());
  return *p_;
}

RealField& SolveScratch::displacement() {
  if (!u_) u_.emplace(f_->grid());
  return *u_;
}

TangentialCompliance::Workspace& SolveScratch::workspace() {
  if (!w_) w_.emplace(f_->workspace());
  return *w_;
}

std::size_t EnergyRelease::unload(const Disc& disc, std::vector<std::uint8_t>& loaded, RealField& u,
                                  SolveScratch& scratch, const ColumnSegments* cover) const {
  const Grid2D& g = f_->grid();
  // The loaded cells of the disc, unloaded, as runs (row, first x, last x).
  thread_local std::vector<std::array<long, 3>> runs;
  runs.clear();
  std::size_t removed = 0;
  disc.for_each_row(g, [&](long row, long first, long last) {
    for (long i = first; i <= last; ++i) {
      const std::size_t k = at(g, i, row);
      if (!loaded[k]) continue;
      loaded[k] = 0;
      ++removed;
      if (!runs.empty() && runs.back()[0] == row && runs.back()[2] + 1 == i)
        runs.back()[2] = i;
      else
        runs.push_back({row, i, i});
    }
  });
  std::size_t remaining = 0;
  for (auto v : loaded) remaining += v;
  std::optional<ColumnSegments> own;
  if (!cover) cover = &own.emplace(g, loaded);
  // u ← u − F p_C, needed on the cells still loaded only: by sums over the
  // runs when (runs) × (cells of the cover) is below the cost of one padded
  // solve, else by FFT. (Measured at n = 512: 0.6–0.8 ns per run and cell;
  // the padded solve ~0.5 ns per point and log2 point.)
  const double n_pad = 4.0 * static_cast<double>(g.size());
  if (static_cast<double>(runs.size()) * static_cast<double>(cover->cells) < n_pad * std::log2(n_pad)) {
    subtract_run_sums(runs, *cover, remaining, u);
    return removed;
  }
  RealField &p = scratch.traction(), &du = scratch.displacement();
  p.fill(0.0);
  for (const auto& [rj, r0, r1] : runs)
    for (long ri = r0; ri <= r1; ++ri) p[at(g, ri, rj)] = sigma_j_;
  f_->displacement(p, du, scratch.workspace());
  for (std::size_t k = 0; k < u.size(); ++k) u[k] -= du[k];
  return removed;
}

}  // namespace wearscale::wear
