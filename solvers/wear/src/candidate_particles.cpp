#include "wearscale/wear/candidate_particles.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <fmt/format.h>

#include "wearscale/bem/contact_clusters.hpp"
#include "wearscale/bem/principal_stresses.hpp"
#include "wearscale/bem/subsurface_stress.hpp"
#include "wearscale/core/errors.hpp"

namespace wearscale::wear {

CrackSites crack_sites(const MicroContactMap& map, double sigma_j, double nu, double sigma_m, double spot) {
  if (!(sigma_j > 0.0) || !std::isfinite(sigma_j))
    throw InputError(fmt::format("crack sites: junction strength σ_j = {} is not allowed; allowed: > 0", sigma_j));
  if (!(sigma_m > 0.0) || !std::isfinite(sigma_m))
    throw InputError(fmt::format("crack sites: tensile strength σ_m = {} is not allowed; allowed: > 0", sigma_m));
  const Grid2D& g = map.grid;
  bem::VectorField traction(g);
  for (std::size_t k = 0; k < g.size(); ++k) traction.x[k] = map.contact[k] ? sigma_j : 0.0;
  bem::SubsurfaceStress solver(g, nu);
  solver.set_traction(traction);
  bem::StressField stress(g);
  solver.stress(0.0, stress);
  bem::PrincipalStresses principal(g);
  bem::principal_stresses(stress, principal);

  if (!(spot >= 0.0 && spot <= 1.0))
    throw InputError(fmt::format("crack sites: spot tolerance {} is not allowed; allowed: 0 … 1", spot));
  RealField mask(g);
  for (std::size_t k = 0; k < g.size(); ++k) mask[k] = map.contact[k] ? 1.0 : 0.0;
  const bem::ContactMap clusters = bem::find_clusters(mask);
  const std::size_t nc = clusters.clusters.size();
  // Edge stresses per point (σ_I on trailing edges, −σ_III on leading ones), and their maximum per micro-contact.
  std::vector<double> tension(g.size(), -1.0), compression(g.size(), -1.0), top_t(nc, 0.0), top_c(nc, 0.0);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) {
      const std::size_t k = g.index(i, j);
      if (!map.contact[k]) continue;
      const auto id = static_cast<std::size_t>(clusters.label[k]);
      const long li = static_cast<long>(i), lj = static_cast<long>(j);
      // The BEM contact is periodic: the stresses and the neighbours wrap.
      const std::size_t behind = g.periodic_index(li - 1, lj), ahead = g.periodic_index(li + 1, lj);
      if (!map.contact[behind]) {
        tension[k] = std::max(principal.first[k], principal.first[behind]);
        top_t[id] = std::max(top_t[id], tension[k]);
      }
      if (!map.contact[ahead]) {
        compression[k] = -std::min(principal.third[k], principal.third[ahead]);
        top_c[id] = std::max(top_c[id], compression[k]);
      }
    }
  CrackSites s;
  s.trailing.assign(g.size(), 0);
  s.leading.assign(g.size(), 0);
  for (std::size_t k = 0; k < g.size(); ++k) {
    if (!map.contact[k]) continue;
    const auto id = static_cast<std::size_t>(clusters.label[k]);
    s.max_tension = std::max(s.max_tension, tension[k]);
    s.max_compression = std::max(s.max_compression, compression[k]);
    s.trailing[k] = tension[k] >= sigma_m && tension[k] >= (1.0 - spot) * top_t[id] ? 1 : 0;           // (4.25a)
    s.leading[k] = compression[k] >= sigma_m && compression[k] >= (1.0 - spot) * top_c[id] ? 1 : 0;  // (4.25b)
  }
  return s;
}

std::vector<Disc> candidate_particles(const MicroContactMap& map, const CrackSites& sites, long max_cells) {
  const Grid2D& g = map.grid;
  const long nx = static_cast<long>(g.nx);
  if (max_cells < 1 || max_cells > nx)
    throw InputError(fmt::format("candidate particles: largest diameter {} cells is not allowed; allowed: 1 … n = {}",
                                 max_cells, nx));
  std::vector<Disc> out;
  std::vector<long> leading;
  for (std::size_t j = 0; j < g.ny; ++j) {
    leading.clear();
    for (long i = 0; i < nx; ++i)
      if (sites.leading[g.index(static_cast<std::size_t>(i), j)]) leading.push_back(i);
    if (leading.empty()) continue;
    for (long i = 0; i < nx; ++i) {
      if (!sites.trailing[g.index(static_cast<std::size_t>(i), j)]) continue;
      for (long b : leading) {
        const long cells = b - i + 1;  // from (a) forward to (b)
        if (cells >= 1 && cells <= max_cells) out.push_back(Disc{i, static_cast<long>(j), cells});
      }
    }
  }
  std::sort(out.begin(), out.end(), [](const Disc& a, const Disc& b) {
    return std::tie(b.cells, a.j, a.i) < std::tie(a.cells, b.j, b.i);
  });
  return out;
}

}  // namespace wearscale::wear
