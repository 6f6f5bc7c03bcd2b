// Fuzzes the strength-table reader: any bytes give a valid table (whose law
// then evaluates to finite, non-negative strengths over its pressure range),
// or InputError naming the problem.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "strength_table_checks.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/strength_table_file.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    fuzz::check_strength_table(materials::parse_strength_table_csv(text, "fuzz.csv"));
  } catch (const InputError&) {
  } catch (const NumericalError&) {
    // a pressure rounding just outside the table's range: a reported failure, not a crash
  }
  return 0;
}
