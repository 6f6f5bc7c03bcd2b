#include "wearscale/wear/detachment.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

namespace {

int max_threads() {
#ifdef _OPENMP
  return omp_in_parallel() ? 1 : omp_get_max_threads();
#else
  return 1;
#endif
}

int thread_id() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

bool overlaps(const Disc& a, const Disc& b) {
  const double dx = a.centre_i() - b.centre_i();
  const double dy = static_cast<double>(a.j - b.j);
  const double r = a.radius_cells() + b.radius_cells();
  return dx * dx + dy * dy < r * r * (1.0 - 1e-12);
}

constexpr double kUnknown = std::numeric_limits<double>::quiet_NaN();

}  // namespace

double DetachmentResult::largest_diameter() const {
  double d = 0.0;
  for (const auto& p : particles) d = std::max(d, p.diameter);
  return d;
}

double surface_energy_for(double d_star, const ShearedJunctions& j) {
  if (!(d_star > 0.0) || !std::isfinite(d_star))
    throw InputError(fmt::format("detachment: critical diameter d* = {} is not allowed; allowed: d* > 0", d_star));
  return d_star * (2.0 - j.poisson) * j.junction_strength * j.junction_strength /
         (12.0 * std::numbers::pi * j.shear_modulus);  // (4.35) solved for γ
}

DetachmentModel::DetachmentModel(const MicroContactMap& map, const ShearedJunctions& j, long max_cells)
    : map_(map), junctions_(j), compliance_(map.grid, j.shear_modulus, j.poisson),
      release_(compliance_, j.junction_strength), u0_(map.grid) {
  const Grid2D& g = map.grid;
  if (std::abs(g.dx() - g.dy()) > 1e-12 * g.dx() || g.nx != g.ny)
    throw InputError(fmt::format("detachment: grid {} is not allowed; allowed: n × n points, square cells",
                                 g.to_string()));
  sites_ = crack_sites(map, j.junction_strength, j.poisson, j.tensile_strength, j.spot);
  candidates_ = candidate_particles(map, sites_, max_cells > 0 ? max_cells : static_cast<long>(g.nx));
  DiscSums counts(g);
  counts.build(map.contact, nullptr);
  contact_count_.resize(candidates_.size());
  for (std::size_t c = 0; c < candidates_.size(); ++c) contact_count_[c] = counts.sum(candidates_[c]);
  self_ = std::make_unique<std::atomic<double>[]>(candidates_.size());
  for (std::size_t c = 0; c < candidates_.size(); ++c) self_[c].store(kUnknown, std::memory_order_relaxed);
  RealField p(g);
  auto w = compliance_.workspace();
  release_.traction(map.contact, p);
  compliance_.displacement(p, u0_, w);
  energy_ = compliance_.energy(p, u0_);
}

DetachmentModel::~DetachmentModel() = default;

double DetachmentModel::self_energy(std::size_t c, const std::vector<std::uint8_t>& loaded, double count) const {
  if (count != contact_count_[c]) return release_.self_energy(candidates_[c], loaded);  // C cut by a particle
  double s = self_[c].load(std::memory_order_relaxed);
  if (std::isnan(s)) {
    s = release_.self_energy(candidates_[c], loaded);
    self_[c].store(s, std::memory_order_relaxed);
  }
  return s;
}

DetachmentResult DetachmentModel::detach(double d_star, const DetachmentOptions& opt) const {
  const Grid2D& g = map_.grid;
  const double gamma = surface_energy_for(d_star, junctions_);
  const double sigma_j = junctions_.junction_strength, da = g.cell_area();
  const bool naive = opt.method == EnergyReleaseMethod::Naive;
  const int threads = opt.parallel ? max_threads() : 1;

  DetachmentResult result;
  std::vector<std::uint8_t> loaded = map_.contact;
  RealField u = u0_;
  double energy = energy_;  // E_el of the present loading (naive only)
  DiscSums work(g), counts(g);
  work.build(loaded, &u);
  counts.build(loaded, nullptr);
  std::vector<Disc> recorded;
  double budget = 0.0;  // Σ ΔE_el − Σ E_ad of the recorded particles (cumulative)

  // Per-thread scratch for the solves.
  std::vector<RealField> sp(static_cast<std::size_t>(threads), RealField(g)), su(sp);
  std::vector<TangentialCompliance::Workspace> ss;
  for (int t = 0; t < threads; ++t) ss.push_back(compliance_.workspace());

  const std::size_t n = candidates_.size();
  const std::size_t chunk = naive ? static_cast<std::size_t>(threads) : std::max<std::size_t>(64, 16 * threads);
  std::vector<double> release(chunk);
  std::vector<signed char> pass(chunk), skipped(chunk);
  while (true) {
    std::size_t found = n;
    for (std::size_t begin = 0; begin < n && found == n; begin += chunk) {
      const std::size_t end = std::min(n, begin + chunk);
      if (naive && opt.max_solves > 0 && result.solves >= opt.max_solves) {
        result.truncated = true;
        return result;
      }
      std::size_t evaluations = 0, bounded = 0;
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(+ : evaluations, bounded) if (threads > 1)
      for (std::size_t c = begin; c < end; ++c) {
        const Disc& disc = candidates_[c];
        signed char& ok = pass[c - begin];
        ok = 0;
        skipped[c - begin] = 0;
        bool blocked = false;
        for (const Disc& r : recorded)
          if (overlaps(disc, r)) {
            blocked = true;
            break;
          }
        if (blocked) {
          skipped[c - begin] = 1;
          continue;
        }
        const double d = disc.diameter(g);
        const double e_ad = std::numbers::pi * gamma * d * d;  // (4.16)
        const double available = opt.cumulative ? budget : 0.0;
        double de;
        if (naive) {
          const auto t = static_cast<std::size_t>(thread_id());
          de = release_.naive_release(disc, loaded, energy, sp[t], su[t], ss[t]);
          ++evaluations;
        } else {
          const double w = sigma_j * da * work.sum(disc);  // ΔA p_C·u ≥ ΔE_el
          if (available + w < e_ad) {
            ++bounded;
            continue;
          }
          de = EnergyRelease::release(w, self_energy(c, loaded, counts.sum(disc)));  // (5.3)
          ++evaluations;
        }
        release[c - begin] = de;
        ok = available + de >= e_ad ? 1 : 0;  // (4.18)
      }
      result.energy_evaluations += evaluations;
      result.bound_rejections += bounded;
      if (naive) result.solves += evaluations;
      for (std::size_t c = begin; c < end; ++c) {  // the sequential procedure stops at the first pass
        ++result.examined;
        result.blocked += static_cast<std::size_t>(skipped[c - begin]);
        if (pass[c - begin]) {
          found = c;
          break;
        }
      }
    }
    if (found == n) break;
    const Disc& disc = candidates_[found];
    const double d = disc.diameter(g);
    WearParticle p;
    p.diameter = d;
    p.x = disc.centre_i() * g.dx();
    p.y = static_cast<double>(disc.j) * g.dy();
    p.volume = std::numbers::pi * d * d * d / 6.0;
    p.energy_release = release[found % chunk];
    p.adhesive_energy = std::numbers::pi * gamma * d * d;
    if (!std::isfinite(p.energy_release))
      throw NumericalError("wear detachment", static_cast<long>(result.particles.size()), "ΔE_el",
                           fmt::format("non-finite energy release for the particle of diameter {}", d));
    p.contact_points = release_.unload(disc, loaded, u, sp[0], su[0], ss[0]);
    ++result.solves;
    if (opt.cumulative) budget += p.energy_release - p.adhesive_energy;
    energy -= p.energy_release;
    result.released_energy += p.energy_release;
    result.wear_volume += p.volume;
    result.particles.push_back(p);
    recorded.push_back(disc);
    work.build(loaded, &u);
    counts.build(loaded, nullptr);
  }
  return result;
}

}  // namespace wearscale::wear
