#include "wearscale/dem/cohesive_law.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/cohesive_kernel.hpp"
#include "wearscale/dem/neighbor_list.hpp"
#include "wearscale/dem/pair_loop.hpp"
#include "wearscale/dem/particles.hpp"

namespace wearscale::dem {

double normal_cross_section(double r_eff, double poisson) {
  return std::numbers::sqrt2 * r_eff * r_eff / (1.0 - 2.0 * poisson);  // (6.51)
}

double tangential_cross_section(double r_eff, double poisson) {
  return std::numbers::sqrt2 * r_eff * r_eff * (1.0 - 4.0 * poisson) /
         ((1.0 - 2.0 * poisson) * (1.0 + poisson));  // (6.52)
}

double elastic_separation(const CohesiveMaterial& m, double radius_sum) {
  return radius_sum * m.tensile_strength / m.young;  // (6.56)
}

double fracture_separation(const CohesiveMaterial& m, double radius_sum) {
  const double d_c = critical_diameter(m);
  if (radius_sum <= d_c) return 4.0 * m.surface_energy / m.tensile_strength;  // (6.57), (6.21)
  return elastic_separation(m, radius_sum) * std::pow(radius_sum / d_c, -m.scaling_exponent);
}

CohesivePair cohesive_pair(const CohesiveMaterial& m, double r_i, double r_j, double m_i,
                           double m_j) {
  const double r_eff = std::min(r_i, r_j);  // (6.53)
  const double sum = r_i + r_j;
  const double m_eff = m_i * m_j / (m_i + m_j);  // (6.61)
  const double damping = 2.0 * (1.0 - m.restitution) / std::numbers::pi;
  CohesivePair p;
  p.k_n = normal_cross_section(r_eff, m.poisson) * m.young / sum;      // (6.54)
  p.k_t = tangential_cross_section(r_eff, m.poisson) * m.young / sum;  // (6.55)
  p.delta_f = fracture_separation(m, sum);
  p.delta_e = std::min(elastic_separation(m, sum), p.delta_f);
  // (6.58) at every size: the thesis' shear strengths follow (6.63) above
  // d_c (Fig. 6.11) through δ_f, which shrinks the cap (6.5) sooner, not
  // through F_m,T (as in its LAMMPS pair style gran/cohesive/history).
  p.f_mt = tangential_cross_section(r_eff, m.poisson) * m.shear_strength;
  p.c_n = damping * std::sqrt(p.k_n * m_eff);                             // (6.59)
  p.c_t = damping * std::sqrt(std::max(p.k_t, 0.0) * m_eff);              // (6.60)
  return p;
}

double normal_force(const CohesivePair& p, double delta_n) {
  if (delta_n <= p.delta_e) return p.k_n * delta_n;  // (6.3)
  if (delta_n <= p.delta_f) return -p.k_n * p.delta_e / (p.delta_f - p.delta_e) * (delta_n - p.delta_f);
  return 0.0;
}

double tangential_cap(const CohesivePair& p, double delta_n) {
  return std::min((p.delta_f - delta_n) / p.delta_f, 1.0) * p.f_mt;  // (6.5)
}

double normal_energy(const CohesivePair& p, double delta_n) {
  if (delta_n >= p.delta_f) return 0.0;
  if (delta_n > p.delta_e) {
    const double gap = p.delta_f - delta_n;
    return -0.5 * p.k_n * p.delta_e * gap * gap / (p.delta_f - p.delta_e);
  }
  return 0.5 * p.k_n * (delta_n * delta_n - p.delta_e * p.delta_f);
}

namespace {
// The second-neighbour gap per unit spacing, compressed by `strain`.
double second_neighbour_gap(double strain) { return std::numbers::sqrt2 * (1.0 - strain) - 1.0; }
}  // namespace

double smallest_hcp_spacing(const CohesiveMaterial& m, double strain) {
  const double gap = second_neighbour_gap(strain);
  if (!(gap > 0.0)) return std::numeric_limits<double>::infinity();
  const double d_c = critical_diameter(m);
  // Below d_c, δ_f = d_min is constant (6.57).
  const double below = minimum_diameter(m) / gap;
  if (below <= d_c) return below;
  // Above d_c, δ_f = d (σ_m,N/E) (d/d_c)^(−s): beyond the gap once
  // (d/d_c)^s ≥ (σ_m,N/E)/gap.
  const double ratio = m.tensile_strength / m.young / gap;
  if (ratio <= 1.0) return d_c;
  if (!(m.scaling_exponent > 0.0)) return std::numeric_limits<double>::infinity();
  return d_c * std::pow(ratio, 1.0 / m.scaling_exponent);
}

void require_hcp_spacing(const std::vector<CohesiveMaterial>& materials, double d0, const std::string& what,
                         double strain) {
  const double gap = second_neighbour_gap(strain) * d0;
  double needed = 0.0;
  const CohesiveMaterial* worst = nullptr;
  double worst_reach = 0.0;
  for (const auto& a : materials)
    for (const auto& b : materials) {
      const CohesiveMaterial m = mix(a, b);
      needed = std::max(needed, smallest_hcp_spacing(m, strain));
      const double reach = fracture_separation(m, d0);
      if (gap < reach && reach > worst_reach) {  // at δ_N = δ_f the force has vanished
        worst = &a;
        worst_reach = reach;
        if (a.name != b.name) worst = nullptr;  // an interface: named below
      }
    }
  if (worst_reach == 0.0) return;
  std::string allowed = "none for these materials (σ_m,N/E ≥ √2 − 1 with s = 0)";
  if (std::isfinite(needed)) {
    // Rounded up, so that the value shown is itself allowed.
    const double unit = std::pow(10.0, std::floor(std::log10(needed)) - 3.0);
    allowed = fmt::format("d0 ≥ {:.6g}", std::ceil(needed / unit) * unit);
  }
  const std::string compressed = strain > 0.0 ? fmt::format(" compressed by {:.3g} %", 100.0 * strain) : "";
  throw InputError(fmt::format(
      "{}: an HCP lattice of d0 = {:.6g}{}{} leaves its second neighbours (√2 d0 apart) a gap of {:.4g}, within the "
      "cohesive reach δ_f = {:.4g}: they would attract in the softening branch of the force law, a negative "
      "stiffness, and the lattice's E and ν would be meaningless. Allowed: {}",
      what, d0, worst != nullptr ? " of " + worst->name : std::string(" (an interface)"), compressed, gap, worst_reach,
      allowed));
}

double critical_time_step(double mass, double k_n) { return std::sqrt(2.0 * mass / k_n); }  // (6.6)
double critical_damping(double mass, double k_n) { return std::sqrt(2.0 * k_n * mass); }    // (6.64)

CohesiveLaw::CohesiveLaw(std::vector<CohesiveMaterial> materials) : materials_(std::move(materials)) {
  if (materials_.empty()) throw InputError("the cohesive DEM force law needs at least one material");
  if (materials_.size() > 255) throw InputError("the cohesive DEM force law allows at most 255 materials");
  for (const auto& m : materials_) require_modelled(m);
  mixed_.reserve(materials_.size() * materials_.size());
  for (const auto& a : materials_)
    for (const auto& b : materials_) mixed_.push_back(mix(a, b));
}

void CohesiveLaw::set_interface(std::size_t a, std::size_t b, const CohesiveMaterial& interface) {
  const std::size_t n = materials_.size();
  if (a >= n || b >= n)
    throw InputError(fmt::format("cohesive law: an interface between materials {} and {} of a table of {}", a, b, n));
  require_modelled(interface);
  mixed_[a * n + b] = interface;
  mixed_[b * n + a] = interface;
}

CohesivePair CohesiveLaw::pair(const Particles& p, std::size_t i, std::size_t j) const {
  return cohesive_pair(pair_material(p.material[i], p.material[j]), p.radius[i], p.radius[j],
                       p.mass[i], p.mass[j]);
}

double CohesiveLaw::reach(double max_radius) const {
  double reach = 0.0;
  for (const auto& m : mixed_) {
    // δ_f is constant below d_c and grows as (r_i + r_j)^(1−s) above it.
    reach = std::max(reach, fracture_separation(m, 2.0 * max_radius));
    reach = std::max(reach, 4.0 * m.surface_energy / m.tensile_strength);
  }
  return reach;
}

double CohesiveLaw::critical_time_step(const Particles& p) const {
  double dt = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto pp = pair(p, i, i);
    dt = std::min(dt, dem::critical_time_step(p.mass[i], pp.k_n));
  }
  return dt;
}

double CohesiveLaw::critical_damping(const Particles& p) const {
  if (p.empty()) return 0.0;
  const auto smallest = static_cast<std::size_t>(
      std::min_element(p.radius.begin(), p.radius.end()) - p.radius.begin());
  return dem::critical_damping(p.mass[smallest], pair(p, smallest, smallest).k_n);
}

void CohesiveLaw::prepare(const Particles& p, const NeighborList& list) {
  const auto& off = list.offsets();
  const auto& nb = list.neighbors();
  const std::size_t n = p.size();
  uniform_ = true;
  for (std::size_t i = 1; i < n && uniform_; ++i)
    uniform_ = p.material[i] == p.material[0] && p.radius[i] == p.radius[0] && p.mass[i] == p.mass[0];
  if (uniform_) {
    // cohesive_pair() of the same inputs: the bits every pair would get.
    if (n > 0) uniform_pair_ = pair(p, 0, 0);
    for (auto* v : {&k_n_, &k_t_, &delta_e_, &delta_f_, &f_mt_, &c_n_, &c_t_}) std::vector<double>().swap(*v);
    return;
  }
  for (auto* v : {&k_n_, &k_t_, &delta_e_, &delta_f_, &f_mt_, &c_n_, &c_t_}) v->resize(list.pairs());
#pragma omp parallel for schedule(static) if (n >= 4096)
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = off[i]; k < off[i + 1]; ++k) {
      const CohesivePair q = pair(p, i, nb[k]);
      k_n_[k] = q.k_n;
      k_t_[k] = q.k_t;
      delta_e_[k] = q.delta_e;
      delta_f_[k] = q.delta_f;
      f_mt_[k] = q.f_mt;
      c_n_[k] = q.c_n;
      c_t_[k] = q.c_t;
    }
}

CohesivePair CohesiveLaw::listed_pair(std::size_t k) const {
  if (uniform_) return uniform_pair_;
  return {k_n_[k], k_t_[k], delta_e_[k], delta_f_[k], f_mt_[k], c_n_[k], c_t_[k]};
}

namespace {

// The law's pair force for one loop, with its switches and the layout of its
// parameters fixed (dispatched once per force evaluation, not per pair), and
// everything it reads held by value or as plain arrays, so that the
// vectorised loop loads nothing it could not hoist.
template <bool Uniform, bool Cohesion, bool Tangential>
struct CohesiveKernel {
  static constexpr int history_doubles = CohesiveLaw::history_doubles;
  CohesivePair uniform;  // Uniform: every pair's parameters
  const double *k_n, *k_t, *delta_e, *delta_f, *f_mt, *c_n, *c_t;  // else per listed pair

  // The cohesive force of §6.1, (6.2)-(6.5): the kernel shared with the LAMMPS pair style.
  PairForce contact(std::size_t k, const PairState& s, const double* hist, double* updated, double dt,
                    bool advance) const {
    const CohesivePair p =
        Uniform ? uniform : CohesivePair{k_n[k], k_t[k], delta_e[k], delta_f[k], f_mt[k], c_n[k], c_t[k]};
    return cohesive_contact<Cohesion, Tangential>(p, s, hist, updated, dt, advance);
  }
};

template <bool Cohesion, bool Tangential>
void run_cohesive_loop(bool uniform, const CohesivePair& u, const double* const* a, PairLoop& loop) {
  if (uniform)
    run_pair_loop(CohesiveKernel<true, Cohesion, Tangential>{u, a[0], a[1], a[2], a[3], a[4], a[5], a[6]}, loop);
  else
    run_pair_loop(CohesiveKernel<false, Cohesion, Tangential>{u, a[0], a[1], a[2], a[3], a[4], a[5], a[6]}, loop);
}
}  // namespace

void CohesiveLaw::add_pair_forces(PairLoop& loop) const {
  const double* const arrays[] = {k_n_.data(),  k_t_.data(), delta_e_.data(), delta_f_.data(),
                                  f_mt_.data(), c_n_.data(), c_t_.data()};
  if (cohesion && tangential)
    run_cohesive_loop<true, true>(uniform_, uniform_pair_, arrays, loop);
  else if (cohesion)
    run_cohesive_loop<true, false>(uniform_, uniform_pair_, arrays, loop);
  else if (tangential)
    run_cohesive_loop<false, true>(uniform_, uniform_pair_, arrays, loop);
  else
    run_cohesive_loop<false, false>(uniform_, uniform_pair_, arrays, loop);
}

void CohesiveLaw::add_pair_energy(const Particles&, std::size_t, std::size_t, std::size_t k, double delta,
                                  const double* h, double& e) const {
  const CohesivePair pp = listed_pair(k);
  if (cohesion) {
    e += normal_energy(pp, delta);
  } else if (delta < 0.0) {
    e += 0.5 * pp.k_n * delta * delta;
  }
  e += 0.5 * pp.k_t * (h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
}

}  // namespace wearscale::dem

WEARSCALE_CONTACT_LAW(cohesive, "the thesis' reversible cohesive pair force (6.2)-(6.5)",
                      [](const ContactLawInputs& in) { return std::make_unique<wearscale::dem::CohesiveLaw>(in.materials); })
