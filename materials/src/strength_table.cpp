#include "wearscale/materials/strength_table.hpp"

#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::materials {

namespace {
constexpr double kGPa = 1e9;
}  // namespace

void validate(const StrengthTable& t, const std::function<std::string(std::size_t)>& where) {
  const std::string name = t.origin.empty() ? std::string("strength table") : t.origin;
  const std::size_t n = t.pressure.size();
  if (t.sigma_max.size() != n || t.sigma_dyn.size() != n)
    throw InputError(fmt::format("{}: columns of different lengths", name));
  for (std::size_t r = 0; r < n; ++r) {
    const double p = t.pressure[r], a = t.sigma_max[r], d = t.sigma_dyn[r];
    if (!std::isfinite(p) || !std::isfinite(a) || !std::isfinite(d))
      throw InputError(fmt::format("{}: NaN or infinite value", where(r)));
    if (p < 0.0) throw InputError(fmt::format("{}: pressure {:g} GPa is negative; allowed: ≥ 0", where(r), p / kGPa));
    if (a < 0.0 || d < 0.0)
      throw InputError(fmt::format("{}: negative strength ({:g}, {:g} GPa); allowed: ≥ 0", where(r), a / kGPa, d / kGPa));
    if (r > 0 && p < t.pressure[r - 1])
      throw InputError(fmt::format("{}: pressure {:g} GPa after {:g} GPa; pressures must not decrease", where(r),
                                   p / kGPa, t.pressure[r - 1] / kGPa));
    if (r > 1 && p == t.pressure[r - 1] && p == t.pressure[r - 2])
      throw InputError(fmt::format("{}: pressure {:g} GPa appears three times; a jump is two rows at one pressure "
                                   "(left and right values)",
                                   where(r), p / kGPa));
  }
  if (n < 2) throw InputError(fmt::format("{}: needs at least two pressures, has {}", name, n));
  if (t.pressure[0] == t.pressure[1] || t.pressure[n - 1] == t.pressure[n - 2])
    throw InputError(fmt::format("{}: a jump (a pressure listed twice) needs rows on both sides of it", name));
  if (t.pressure.front() == t.pressure.back()) throw InputError(fmt::format("{}: all pressures are equal", name));
}

std::string StrengthTable::info(const std::string& key) const {
  for (const auto& [k, v] : provenance)
    if (k == key) return v;
  return {};
}

void validate(const StrengthTable& t) {
  const std::string name = t.origin.empty() ? std::string("strength table") : t.origin;
  validate(t, [&](std::size_t r) { return fmt::format("{}: row {}", name, r + 1); });
}

}  // namespace wearscale::materials
