// Fuzzes the strength-table reader: any bytes give a valid table (whose law
// then evaluates to finite, non-negative strengths over its pressure range),
// or InputError naming the problem.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "wearscale/core/errors.hpp"
#include "wearscale/materials/strength_law.hpp"
#include "wearscale/materials/strength_table.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    auto table = materials::parse_strength_table_csv(text, "fuzz.csv");
    materials::validate(table);  // what was read passes the writer's own check
    const materials::StrengthLaw law(std::move(table));
    const double lo = law.min_pressure(), hi = law.max_pressure();
    for (int k = 0; k <= 16; ++k) {
      const double p = lo + (hi - lo) * k / 16.0;
      const double a = law.sigma_max(p), d = law.sigma_dyn(p);
      if (!std::isfinite(a) || !std::isfinite(d) || a < 0.0 || d < 0.0) std::abort();
    }
  } catch (const InputError&) {
  } catch (const NumericalError&) {
    // a pressure rounding just outside the table's range: a reported failure, not a crash
  }
  return 0;
}
