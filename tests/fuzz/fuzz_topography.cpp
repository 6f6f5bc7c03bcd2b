// Fuzzes the text topography reader: any bytes give a finite height grid of
// the size the text says, or InputError naming the problem.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "topography_checks.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/topography_io.hpp"

using namespace wearscale;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::string_view text(reinterpret_cast<const char*>(data + 1), size - 1);
  try {
    fuzz::check_topography(bem::parse_topography_text(text, "fuzz.txt", fuzz::given_size(data)));
  } catch (const InputError&) {
  }
  return 0;
}
