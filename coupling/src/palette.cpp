#include "wearscale/coupling/palette.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace wearscale::coupling::okabe_ito {

std::string tint(std::string_view colour, double fraction) {
  const auto bad = [&] {
    return std::invalid_argument(fmt::format("tint('{}', {}): a colour '#RRGGBB' and a fraction in [0, 1]", colour,
                                             fraction));
  };
  if (colour.size() != 7 || colour[0] != '#' || !(fraction >= 0.0 && fraction <= 1.0)) throw bad();
  std::string out = "#";
  for (std::size_t k = 1; k < 7; k += 2) {
    int channel = 0;
    for (const char c : colour.substr(k, 2)) {
      const int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : c >= 'A' && c <= 'F' ? c - 'A' + 10 : -1;
      if (digit < 0) throw bad();
      channel = 16 * channel + digit;
    }
    out += fmt::format("{:02X}", static_cast<int>(std::lround(255.0 - fraction * (255.0 - channel))));
  }
  return out;
}

}  // namespace wearscale::coupling::okabe_ito
