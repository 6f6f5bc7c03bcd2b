#include "wearscale/wear/energy_release.hpp"

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

struct BoxScratch {
  std::shared_ptr<const FFTPlan> plan;
  RealField mask;
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
    s->spectrum = ComplexField::spectrum_of(g);
  }
  return *s;
}

}  // namespace

DiscSums::DiscSums(const Grid2D& grid) : grid_(grid), prefix_(grid.ny * (grid.nx + 1), 0.0) {}

void DiscSums::build(const std::vector<std::uint8_t>& mask, const RealField* values) {
  const std::size_t nx = grid_.nx, ny = grid_.ny, stride = nx + 1;
#pragma omp parallel for schedule(static) if (nx * ny > 65536)
  for (std::size_t j = 0; j < ny; ++j) {
    double* p = prefix_.data() + j * stride;
    p[0] = 0.0;
    for (std::size_t m = 0; m < nx; ++m) {
      const std::size_t k = grid_.index(m, j);
      const double v = mask[k] ? (values ? (*values)[k] : 1.0) : 0.0;
      p[m + 1] = p[m] + v;
    }
  }
}

double DiscSums::sum(const Disc& disc) const {
  const std::size_t stride = grid_.nx + 1;
  double s = 0.0;
  disc.for_each_row(grid_, [&](long row, long first, long last) {
    const double* p = prefix_.data() + static_cast<std::size_t>(row) * stride;
    s += p[last + 1] - p[first];
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
  s.mask.fill(0.0);
  for (const auto& [i, j] : cells) s.mask(static_cast<std::size_t>(i - i_min), static_cast<std::size_t>(j - j_min)) = 1.0;
  s.plan->forward(s.mask, s.spectrum);
  for (auto& z : s.spectrum) z = std::norm(z);
  s.plan->backward(s.spectrum, s.mask);
  double sum = 0.0;
  const long lbx = static_cast<long>(bx), lby = static_cast<long>(by), lm = static_cast<long>(m);
  for (long di = -(lbx - 1); di < lbx; ++di)
    for (long dj = -(lby - 1); dj < lby; ++dj) {
      const double count = std::floor(  // a pair count, ≥ 0, up to round-off
          s.mask(static_cast<std::size_t>((di + lm) % lm), static_cast<std::size_t>((dj + lm) % lm)) + 0.5);
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

std::size_t EnergyRelease::unload(const Disc& disc, std::vector<std::uint8_t>& loaded, RealField& u, RealField& p,
                                  RealField& du, TangentialCompliance::Workspace& w) const {
  const Grid2D& g = f_->grid();
  thread_local std::vector<std::pair<long, long>> removed;
  removed.clear();
  disc.for_each_row(g, [&](long row, long first, long last) {
    for (long i = first; i <= last; ++i) {
      const std::size_t k = at(g, i, row);
      if (loaded[k]) {
        loaded[k] = 0;
        removed.emplace_back(i, row);
      }
    }
  });
  std::size_t remaining = 0;
  for (auto v : loaded) remaining += v;
  // u ← u − F p_C, needed on the cells still loaded only: by the kernel when
  // |C| × (loaded cells) is below the cost of one padded solve, else by FFT.
  const double n_pad = 4.0 * static_cast<double>(g.size());
  // (a kernel lookup ~1.5 ns, a padded FFT ~0.85 ns per point and log2 point, two of them: measured at n = 512)
  if (static_cast<double>(removed.size()) * static_cast<double>(remaining) < n_pad * std::log2(n_pad)) {
    const long nx = static_cast<long>(g.nx), ny = static_cast<long>(g.ny);
#pragma omp parallel for schedule(static) if (!omp_in_parallel() && remaining > 4096)
    for (long i = 0; i < nx; ++i)
      for (long j = 0; j < ny; ++j) {
        const std::size_t k = at(g, i, j);
        if (!loaded[k]) continue;
        double s = 0.0;
        for (const auto& [ri, rj] : removed) s += f_->kernel(i - ri, j - rj);
        u[k] -= sigma_j_ * s;
      }
    return removed.size();
  }
  p.fill(0.0);
  for (const auto& [ri, rj] : removed) p[at(g, ri, rj)] = sigma_j_;
  f_->displacement(p, du, w);
  for (std::size_t k = 0; k < u.size(); ++k) u[k] -= du[k];
  return removed.size();
}

}  // namespace wearscale::wear
