#include "surface_sides.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <vector>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/units.hpp"

namespace wearscale::studies {

namespace {

// A length from "1e-4" (metres) or "100 um"; nullopt for anything else.
std::optional<double> length_of(std::string text) {
  const auto b = text.find_first_not_of(" \t"), e = text.find_last_not_of(" \t");
  text = b == std::string::npos ? std::string() : text.substr(b, e - b + 1);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size()) {
    try {
      const auto q = units::parse_quantity(text);
      if (!(q.dimension == units::length)) return std::nullopt;
      v = q.value;
    } catch (const std::exception&) {
      return std::nullopt;
    }
  }
  if (!std::isfinite(v) || v <= 0.0) return std::nullopt;
  return v;
}

}  // namespace

bem::TopographySize read_sides(const Config& c, const std::string& key) {
  bem::TopographySize size;
  c.mark_used(key);
  if (!c.has(key)) return size;
  std::vector<std::string> parts;
  try {
    parts = c.values_as_text(key);  // [Lx, Ly]
  } catch (const InputError&) {
    std::string text;
    try {
      text = c.string(key);  // "Lx,Ly" or "100 um"
    } catch (const InputError&) {
      size.lx = c.number(key, Range::positive(), units::length);  // a number: metres
      return size;
    }
    for (std::size_t start = 0;;) {
      const std::size_t comma = text.find(',', start);
      parts.push_back(text.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
  }
  const std::string allowed = "a positive length in metres (1e-4) or with a unit (\"100 um\"), or two: Lx,Ly";
  if (parts.size() > 2) throw c.error(key, "more than two sides", allowed);
  std::vector<double> sides;
  for (const auto& p : parts) {
    const auto v = length_of(p);
    if (!v) throw c.error(key, "not a length", allowed);
    sides.push_back(*v);
  }
  size.lx = sides[0];
  if (sides.size() > 1) size.ly = sides[1];
  return size;
}

}  // namespace wearscale::studies
