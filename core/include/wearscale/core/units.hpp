#pragma once
// SI units, prefixes and physical constants. wearscale computes in SI; unit
// strings such as "8 mm/s" or "3 um" are converted at the edges only.
#include <array>
#include <numbers>
#include <string>
#include <string_view>

namespace wearscale::units {

// Prefixes and common multiples, to write `3.0 * units::micro * units::m`.
inline constexpr double pico = 1e-12, nano = 1e-9, micro = 1e-6, milli = 1e-3, centi = 1e-2,
                        kilo = 1e3, mega = 1e6, giga = 1e9, tera = 1e12;
inline constexpr double m = 1.0, s = 1.0, kg = 1.0, N = 1.0, Pa = 1.0, J = 1.0, K = 1.0;
inline constexpr double nm = 1e-9, um = 1e-6, mm = 1e-3, angstrom = 1e-10;
inline constexpr double MPa = 1e6, GPa = 1e9;

// Physical constants (CODATA 2018, exact where SI defines them).
inline constexpr double boltzmann = 1.380649e-23;        // J/K
inline constexpr double avogadro = 6.02214076e23;        // 1/mol
inline constexpr double atomic_mass_unit = 1.66053906660e-27;  // kg
inline constexpr double pi = std::numbers::pi;

/// Physical dimension as exponents of (kg, m, s, K).
struct Dimension {
  std::array<int, 4> exponent{0, 0, 0, 0};
  friend bool operator==(const Dimension&, const Dimension&) = default;
  Dimension operator*(const Dimension& o) const;
  Dimension operator/(const Dimension& o) const;
  Dimension pow(int p) const;
  /// "m/s", "Pa", "1" (dimensionless): a readable SI form.
  std::string to_string() const;
};

inline constexpr Dimension dimensionless{};
inline constexpr Dimension length{{0, 1, 0, 0}};
inline constexpr Dimension time{{0, 0, 1, 0}};
inline constexpr Dimension mass{{1, 0, 0, 0}};
inline constexpr Dimension temperature{{0, 0, 0, 1}};
inline constexpr Dimension velocity{{0, 1, -1, 0}};
inline constexpr Dimension force{{1, 1, -2, 0}};
inline constexpr Dimension pressure{{1, -1, -2, 0}};
inline constexpr Dimension energy{{1, 2, -2, 0}};
inline constexpr Dimension surface_energy{{1, 0, -2, 0}};  // J/m^2 = N/m
inline constexpr Dimension density{{1, -3, 0, 0}};
inline constexpr Dimension frequency{{0, 0, -1, 0}};

/// A value converted to SI with its dimension.
struct Quantity {
  double value;
  Dimension dimension;
};

/// Parses "<number> <unit>" such as "8 mm/s", "3 um", "1.5e-4 GPa", "2 kg/m^3",
/// "1.2 J/m^2". Prefixes p n u µ m c k M G T on m, g, s, N, Pa, J, W, Hz, K;
/// also min, h, Å. Throws std::invalid_argument with the offending token.
Quantity parse_quantity(std::string_view text);

}  // namespace wearscale::units
