#include "wearscale/io/key_table.hpp"

#include <cmath>

#include <fmt/ranges.h>

namespace wearscale::key_table_detail {

// As a case writes it: the shortest form that reads back, "inf" for infinity.
std::string default_text(double v) {
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  return fmt::format("{}", v);
}

std::string joined(const std::vector<std::string>& texts, const std::string& separator) {
  return fmt::format("{}", fmt::join(texts, separator));
}

std::string joined_choices(const std::vector<std::string>& names) { return fmt::format("{}", fmt::join(names, " | ")); }

}  // namespace wearscale::key_table_detail
