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
    : DetachmentModel(map, j, std::make_shared<const TangentialCompliance>(map.grid, j.shear_modulus, j.poisson),
                      max_cells) {}

DetachmentModel::DetachmentModel(const MicroContactMap& map, const ShearedJunctions& j,
                                 std::shared_ptr<const TangentialCompliance> compliance, long max_cells)
    : map_(map), junctions_(j), compliance_(std::move(compliance)), release_(*compliance_, j.junction_strength),
      cover_(map.grid, map.contact), u0_(map.grid) {
  const Grid2D& g = map.grid;
  if (!(compliance_->grid() == g) || compliance_->shear_modulus() != j.shear_modulus ||
      compliance_->poisson() != j.poisson)
    throw InputError(fmt::format("detachment: the compliance given (grid {}, G = {}, ν = {}) is not the map's "
                                 "(grid {}, G = {}, ν = {})",
                                 compliance_->grid().to_string(), compliance_->shear_modulus(),
                                 compliance_->poisson(), g.to_string(), j.shear_modulus, j.poisson));
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
  auto w = compliance_->workspace();
  release_.traction(map.contact, p);
  compliance_->displacement(p, u0_, w);
  energy_ = compliance_->energy(p, u0_);
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
  std::vector<std::uint8_t> blocked(candidates_.size(), 0);  // overlaps a recorded particle
  // The last W_C of each candidate (an upper bound of its W_C from then on)
  // and a margin of 1e-9 of the whole loading's ΔA p·u, far above the
  // round-off of the prefix sums (n ε of it).
  std::vector<double> work_bound(candidates_.size(), std::numeric_limits<double>::infinity());
  double total_work = 0.0;
  for (std::size_t k = 0; k < u.size(); ++k) total_work += loaded[k] ? u[k] : 0.0;
  const double margin = 1e-9 * sigma_j * da * total_work;
  double budget = 0.0;  // Σ ΔE_el − Σ E_ad of the recorded particles (cumulative)

  // Scratch for the full solves: per thread for the naive baseline; the fast
  // model needs one only when a particle is unloaded by a padded solve.
  std::vector<SolveScratch> scratch;
  for (int t = 0; t < (naive ? threads : 1); ++t) scratch.emplace_back(*compliance_);

  // Each pass walks the candidates largest first and stops at the first that
  // detaches. The fast model evaluates the unblocked ones one at a time (in
  // cumulative mode most candidates evaluated detach, so evaluating ahead is
  // mostly wasted; its threads work inside an evaluation and an unloading
  // instead), the naive baseline `threads` at a time in parallel.
  const std::size_t n = candidates_.size();
  const std::size_t group_size = naive ? static_cast<std::size_t>(threads) : 1;
  std::vector<std::size_t> group;
  std::vector<double> release(group_size);
  std::vector<signed char> pass(group_size);
  std::size_t last = n;  // the group member that detached
  while (true) {
    std::size_t found = n;
    for (std::size_t next = 0; next < n && found == n;) {
      if (naive && opt.max_solves > 0 && result.solves >= opt.max_solves) {
        result.truncated = true;
        return result;
      }
      group.clear();
      std::size_t stop = next;
      for (; stop < n && group.size() < group_size; ++stop)
        if (!blocked[stop]) group.push_back(stop);
      const auto members = static_cast<long>(group.size());
      const double available = opt.cumulative ? budget : 0.0;
      std::size_t evaluations = 0, bounded = 0;
      if (!naive)
        // W_C = ΔA p_C·u ≥ ΔE_el first, on this thread (its prefix sums are
        // brought up to date here). W_C only falls as particles are unloaded
        // (u falls, C∩loaded shrinks), so a candidate whose last W_C, plus a
        // margin far above the round-off of the sums, is short of E_ad is
        // still short of it: rejected without summing again.
        for (long m = 0; m < members; ++m) {
          const std::size_t c = group[static_cast<std::size_t>(m)];
          const Disc& disc = candidates_[c];
          const double d = disc.diameter(g);
          const double e_ad = std::numbers::pi * gamma * d * d;  // (4.16)
          pass[static_cast<std::size_t>(m)] = 0;
          if (available + work_bound[c] + margin < e_ad) {
            ++bounded;
            continue;
          }
          work.prepare(disc);
          const double w = sigma_j * da * work.sum(disc);
          work_bound[c] = w;
          if (available + w < e_ad) {
            ++bounded;
            continue;
          }
          counts.prepare(disc);
          pass[static_cast<std::size_t>(m)] = -1;  // to evaluate
          release[static_cast<std::size_t>(m)] = w;
        }
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads) reduction(+ : evaluations) if (members > 1)
      for (long m = 0; m < members; ++m) {
        const std::size_t c = group[static_cast<std::size_t>(m)];
        const Disc& disc = candidates_[c];
        signed char& ok = pass[static_cast<std::size_t>(m)];
        if (!naive && ok == 0) continue;  // bounded
        const double d = disc.diameter(g);
        const double e_ad = std::numbers::pi * gamma * d * d;  // (4.16)
        double de;
        if (naive) {
          const auto t = static_cast<std::size_t>(thread_id());
          de = release_.naive_release(disc, loaded, energy, scratch[t].traction(), scratch[t].displacement(),
                                      scratch[t].workspace());
        } else {
          const double w = release[static_cast<std::size_t>(m)];
          de = EnergyRelease::release(w, self_energy(c, loaded, counts.sum(disc)));  // (5.3)
        }
        ++evaluations;
        release[static_cast<std::size_t>(m)] = de;
        ok = available + de >= e_ad ? 1 : 0;  // (4.18)
      }
      result.energy_evaluations += evaluations;
      result.bound_rejections += bounded;
      if (naive) result.solves += evaluations;
      for (std::size_t c = next, m = 0; c < stop; ++c) {  // the sequential procedure stops at the first pass
        ++result.examined;
        if (blocked[c]) {
          ++result.blocked;
          continue;
        }
        if (pass[m]) {
          found = c;
          last = m;
          break;
        }
        ++m;
      }
      next = stop;
    }
    if (found == n) break;
    const Disc& disc = candidates_[found];
    const double d = disc.diameter(g);
    WearParticle p;
    p.diameter = d;
    p.x = disc.centre_i() * g.dx();
    p.y = static_cast<double>(disc.j) * g.dy();
    p.volume = std::numbers::pi * d * d * d / 6.0;
    p.energy_release = release[last];
    p.adhesive_energy = std::numbers::pi * gamma * d * d;
    if (!std::isfinite(p.energy_release))
      throw NumericalError("wear detachment", static_cast<long>(result.particles.size()), "ΔE_el",
                           fmt::format("non-finite energy release for the particle of diameter {}", d));
    p.contact_points = release_.unload(disc, loaded, u, scratch.front(), &cover_);
    ++result.solves;
    if (opt.cumulative) budget += p.energy_release - p.adhesive_energy;
    energy -= p.energy_release;
    result.released_energy += p.energy_release;
    result.wear_volume += p.volume;
    result.particles.push_back(p);
    for (std::size_t c = 0; c < n; ++c)
      if (!blocked[c] && overlaps(candidates_[c], disc)) blocked[c] = 1;
    work.stale();  // summed again where the next passes look
    counts.stale();
  }
  return result;
}

}  // namespace wearscale::wear
