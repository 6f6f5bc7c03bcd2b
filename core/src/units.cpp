#include "wearscale/core/units.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace wearscale::units {

Dimension Dimension::operator*(const Dimension& o) const {
  Dimension d;
  for (std::size_t i = 0; i < 4; ++i) d.exponent[i] = exponent[i] + o.exponent[i];
  return d;
}
Dimension Dimension::operator/(const Dimension& o) const { return *this * o.pow(-1); }
Dimension Dimension::pow(int p) const {
  Dimension d;
  for (std::size_t i = 0; i < 4; ++i) d.exponent[i] = exponent[i] * p;
  return d;
}

std::string Dimension::to_string() const {
  static const std::vector<std::pair<Dimension, std::string>> named = {
      {pressure, "Pa"}, {force, "N"}, {energy, "J"}, {surface_energy, "N/m"},
      {velocity, "m/s"}, {density, "kg/m^3"}, {frequency, "1/s"}};
  for (const auto& [d, name] : named)
    if (d == *this) return name;
  static const char* base[4] = {"kg", "m", "s", "K"};
  std::string out;
  for (std::size_t i = 0; i < 4; ++i) {
    if (exponent[i] == 0) continue;
    if (!out.empty()) out += "·";
    out += base[i];
    if (exponent[i] != 1) out += "^" + std::to_string(exponent[i]);
  }
  return out.empty() ? "1" : out;
}

namespace {

constexpr int kMaxExponent = 12;          // of one unit symbol: m^12 is already absurd
constexpr int kMaxTotalExponent = 1000;   // of the whole quantity, far from int overflow

struct UnitDef {
  std::string_view symbol;
  double factor;
  Dimension dim;
  bool prefixable;
};

const std::vector<UnitDef>& unit_table() {
  static const std::vector<UnitDef> table = {
      {"m", 1.0, length, true},        {"g", 1e-3, mass, true},
      {"s", 1.0, time, true},          {"K", 1.0, temperature, false},
      {"N", 1.0, force, true},         {"Pa", 1.0, pressure, true},
      {"J", 1.0, energy, true},        {"W", 1.0, energy / time, true},
      {"Hz", 1.0, frequency, true},    {"min", 60.0, time, false},
      {"h", 3600.0, time, false},      {"Å", 1e-10, length, false},
      {"Angstrom", 1e-10, length, false}, {"bar", 1e5, pressure, false},
  };
  return table;
}

double prefix_factor(std::string_view p) {
  if (p == "p") return pico;
  if (p == "n") return nano;
  if (p == "u" || p == "µ" || p == "μ") return micro;
  if (p == "m") return milli;
  if (p == "c") return centi;
  if (p == "k") return kilo;
  if (p == "M") return mega;
  if (p == "G") return giga;
  if (p == "T") return tera;
  return 0.0;
}

// One unit symbol, possibly prefixed, e.g. "mm", "GPa", "µm", "kg".
std::pair<double, Dimension> parse_symbol(std::string_view sym) {
  for (const auto& u : unit_table())
    if (sym == u.symbol) return {u.factor, u.dim};
  for (const auto& u : unit_table()) {
    if (!u.prefixable || sym.size() <= u.symbol.size() || !sym.ends_with(u.symbol)) continue;
    double f = prefix_factor(sym.substr(0, sym.size() - u.symbol.size()));
    if (f != 0.0) return {f * u.factor, u.dim};
  }
  throw std::invalid_argument("unknown unit '" + std::string(sym) + "'");
}

}  // namespace

Quantity parse_quantity(std::string_view text) {
  auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  std::size_t pos = 0;
  while (pos < text.size() && is_space(text[pos])) ++pos;
  double value = 0.0;
  auto [end, ec] = std::from_chars(text.data() + pos, text.data() + text.size(), value);
  if (ec != std::errc()) throw std::invalid_argument("expected a number at the start of '" + std::string(text) + "'");
  pos = static_cast<std::size_t>(end - text.data());

  double factor = 1.0;
  Dimension dim{};
  bool divide = false;
  bool any_unit = false;
  while (pos < text.size()) {
    char c = text[pos];
    if (is_space(c) || c == '*') { ++pos; continue; }
    if (c == '/') { divide = true; ++pos; continue; }
    std::size_t start = pos;
    while (pos < text.size() && !is_space(text[pos]) && text[pos] != '*' && text[pos] != '/' &&
           text[pos] != '^')
      ++pos;
    auto [f, d] = parse_symbol(text.substr(start, pos - start));
    int power = 1;
    if (pos < text.size() && text[pos] == '^') {
      ++pos;
      auto [e2, ec2] = std::from_chars(text.data() + pos, text.data() + text.size(), power);
      if (ec2 != std::errc()) throw std::invalid_argument("expected an integer exponent after '^' in '" + std::string(text) + "'");
      // Bounded so that dimension exponents cannot overflow (found by fuzzing: "Pa^1553714283").
      if (power < -kMaxExponent || power > kMaxExponent)
        throw std::invalid_argument("exponent " + std::to_string(power) + " in '" + std::string(text) +
                                    "' is out of range; allowed: -" + std::to_string(kMaxExponent) + " to " +
                                    std::to_string(kMaxExponent));
      pos = static_cast<std::size_t>(e2 - text.data());
    }
    if (divide) power = -power;
    factor *= std::pow(f, power);
    dim = dim * d.pow(power);
    divide = false;
    any_unit = true;
  }
  if (divide) throw std::invalid_argument("dangling '/' in '" + std::string(text) + "'");
  (void)any_unit;
  const double si = value * factor;
  if (std::isfinite(value) && !std::isfinite(si))
    throw std::invalid_argument("'" + std::string(text) + "' overflows in SI units");
  for (int e : dim.exponent)
    if (e < -kMaxTotalExponent || e > kMaxTotalExponent)
      throw std::invalid_argument("'" + std::string(text) + "' has an implausible dimension");
  return {si, dim};
}

}  // namespace wearscale::units
