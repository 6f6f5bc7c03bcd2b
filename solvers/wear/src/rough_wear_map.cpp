#include "wearscale/wear/rough_wear_map.hpp"

#include <chrono>
#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"

namespace wearscale::wear {

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

void validate(const RoughWearMapSpec& s) {
  validate(s.surface);
  if (s.seeds.empty() || s.seeds.size() > 1000)
    throw InputError(fmt::format("rough wear map: {} seeds; allowed: 1 … 1000", s.seeds.size()));
  if (s.loads.size() > 1000 || s.critical_diameters.size() > 1000)
    throw InputError(fmt::format("rough wear map: {} p̃_N and {} d*/L values; allowed: at most 1000 each (as the "
                                 "CLI's n_loads, n_dstar)",
                                 s.loads.size(), s.critical_diameters.size()));
  if (s.loads.empty() || s.critical_diameters.empty())
    throw InputError("rough wear map: the p̃_N and d*/L axes need at least one value each");
  for (std::size_t k = 0; k < s.loads.size(); ++k)
    if (!(s.loads[k] > 0.0 && s.loads[k] < 1.0) || (k > 0 && !(s.loads[k] > s.loads[k - 1])))
      throw InputError(fmt::format("rough wear map: p̃_N = {} (value {}) is not allowed; allowed: increasing, in (0, 1)",
                                   s.loads[k], k + 1));
  for (double d : s.critical_diameters)
    if (!(d > 0.0) || !std::isfinite(d))
      throw InputError(fmt::format("rough wear map: d*/L = {} is not allowed; allowed: > 0", d));
  if (!(s.tensile_strength > 0.0) || !std::isfinite(s.tensile_strength))
    throw InputError(fmt::format("rough wear map: σ_m/σ_j = {} is not allowed; allowed: > 0", s.tensile_strength));
  if (!(s.spot >= 0.0 && s.spot <= 1.0))
    throw InputError(fmt::format("rough wear map: spot = {} is not allowed; allowed: 0 … 1", s.spot));
  if (!(s.invalid_diameter > 0.0 && s.invalid_diameter <= 1.0))
    throw InputError(fmt::format("rough wear map: invalid diameter {} L is not allowed; allowed: (0, 1]",
                                 s.invalid_diameter));
}

SurfaceWearMap rough_wear_map_surface(const RoughWearMapSpec& spec, std::size_t index,
                                      const std::function<void(std::size_t, std::size_t)>& progress) {
  validate(spec);
  if (index >= spec.seeds.size())
    throw InputError(fmt::format("rough wear map: surface {} is not allowed; allowed: 0 … {}", index,
                                 spec.seeds.size() - 1));
  const std::size_t nl = spec.loads.size(), nd = spec.critical_diameters.size();
  SurfaceWearMap out;
  out.index = index;
  out.count.resize(nl * nd), out.volume.resize(nl * nd), out.largest.resize(nl * nd), out.contact_fraction.resize(nl);
  const double nu = spec.surface.poisson;
  ShearedJunctions junctions{1.0, 1.0 / (2.0 * (1.0 + nu)), nu, spec.tensile_strength, spec.spot};  // E = 1, σ_j = 1
  std::vector<std::vector<WearParticle>> found(nd);
  RoughContactSeries series(spec.surface, spec.seeds[index]);
  for (std::size_t l = 0; l < nl; ++l) {
    throw_if_interrupted("rough wear map");
    auto t0 = std::chrono::steady_clock::now();
    const MicroContactMap map = series.at_load(spec.loads[l]);
    out.contact_fraction[l] = map.contact_fraction();
    out.contact_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    const DetachmentModel model(map, junctions);
    out.candidates += model.candidates().size();
    out.setup_seconds += seconds_since(t0);
    t0 = std::chrono::steady_clock::now();
    DetachmentOptions opt = spec.options;
    opt.parallel = false;  // the d* values run in parallel instead
    std::size_t evaluations = 0, solves = 0;
#pragma omp parallel for schedule(dynamic, 1) reduction(+ : evaluations, solves)
    for (std::size_t d = 0; d < nd; ++d) {
      const auto r = model.detach(spec.critical_diameters[d], opt);  // lengths in units of L = 1
      out.count[l * nd + d] = static_cast<double>(r.particles.size());
      out.volume[l * nd + d] = r.wear_volume;
      out.largest[l * nd + d] = r.largest_diameter();
      evaluations += r.energy_evaluations;
      solves += r.solves;
      found[d] = r.particles;
    }
    out.detach_seconds += seconds_since(t0);
    out.energy_evaluations += evaluations;
    out.solves += solves;
    for (std::size_t d = 0; d < nd; ++d)
      for (const auto& p : found[d]) out.particles.push_back({spec.seeds[index], l, d, p.x, p.y, p.diameter});
    if (progress) progress(l + 1, nl);
  }
  return out;
}

RoughWearMap combine_surfaces(const RoughWearMapSpec& spec, const std::vector<SurfaceWearMap>& surfaces) {
  const std::size_t nl = spec.loads.size(), nd = spec.critical_diameters.size(), ns = spec.seeds.size();
  if (surfaces.size() != ns)
    throw InputError(fmt::format("rough wear map: {} surfaces to combine, the spec has {} seeds", surfaces.size(), ns));
  for (std::size_t s = 0; s < ns; ++s)
    if (surfaces[s].index != s || surfaces[s].count.size() != nl * nd || surfaces[s].contact_fraction.size() != nl)
      throw InputError(fmt::format("rough wear map: surface {} of {} does not belong to this map", s + 1, ns));
  RoughWearMap out;
  out.spec = spec;
  for (const auto& f : surfaces) {
    out.contact_seconds += f.contact_seconds, out.setup_seconds += f.setup_seconds;
    out.detach_seconds += f.detach_seconds, out.candidates += f.candidates;
    out.energy_evaluations += f.energy_evaluations, out.solves += f.solves;
    out.particles.insert(out.particles.end(), f.particles.begin(), f.particles.end());
  }
  auto mean_sd = [&](std::vector<double> SurfaceWearMap::*v, std::size_t i, double& mean, double& sd) {
    mean = 0.0;
    for (const auto& f : surfaces) mean += (f.*v)[i];
    mean /= static_cast<double>(ns);
    double var = 0.0;
    for (const auto& f : surfaces) var += ((f.*v)[i] - mean) * ((f.*v)[i] - mean);
    sd = ns > 1 ? std::sqrt(var / static_cast<double>(ns - 1)) : 0.0;  // sample standard deviation
  };
  out.pixels.resize(nl * nd);
  for (std::size_t l = 0; l < nl; ++l)
    for (std::size_t d = 0; d < nd; ++d) {
      WearMapPixel& p = out.pixels[l * nd + d];
      p.load = spec.loads[l];
      p.critical_diameter = spec.critical_diameters[d];
      mean_sd(&SurfaceWearMap::count, l * nd + d, p.count_mean, p.count_sd);
      mean_sd(&SurfaceWearMap::volume, l * nd + d, p.volume_mean, p.volume_sd);
      double unused = 0.0;
      mean_sd(&SurfaceWearMap::largest, l * nd + d, p.largest_mean, unused);
      for (const auto& f : surfaces) p.contact_fraction += f.contact_fraction[l] / static_cast<double>(ns);
      p.valid = p.largest_mean < spec.invalid_diameter;
    }
  return out;
}

RoughWearMap rough_wear_map(const RoughWearMapSpec& spec, const std::function<void(std::size_t, std::size_t)>& progress) {
  validate(spec);
  const std::size_t nl = spec.loads.size(), ns = spec.seeds.size();
  std::vector<SurfaceWearMap> surfaces;
  for (std::size_t s = 0; s < ns; ++s)
    surfaces.push_back(rough_wear_map_surface(spec, s, [&](std::size_t l, std::size_t) {
      if (progress) progress(s * nl + l, ns * nl);
    }));
  return combine_surfaces(spec, surfaces);
}

}  // namespace wearscale::wear
