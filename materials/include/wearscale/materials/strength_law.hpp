#pragma once
// Pressure-dependent shear strengths σ_max(p), σ_dyn(p) of a material,
// interpolated linearly (so monotone between samples) in a StrengthTable.
// A pressure listed twice is a jump: below it the first value holds, at and
// above it the second (Fig. 9.18: "10.6 GPa for p < 20 GPa, 4 GPa above").
#include <memory>
#include <string>
#include <vector>

#include "wearscale/materials/strength_table.hpp"

namespace wearscale::materials {

/// What happens at a pressure beyond the table's last row (or below its first).
enum class OutsideTable {
  Error,  ///< NumericalError naming the table, the pressure and the range (default)
  Clamp,  ///< the value at the nearest end of the table, held constant
};

class StrengthLaw {
 public:
  explicit StrengthLaw(StrengthTable table, OutsideTable outside = OutsideTable::Error);
  /// A pressure-independent law σ_max = σ_dyn = value on [0, p_max] (e.g. the
  /// ideal strengths of Table 2.1, or the 7.5 GPa of the DEM fit (7.11)).
  static StrengthLaw constant(const std::string& material, double value, double p_max, const std::string& source);

  double sigma_max(double p) const;
  double sigma_dyn(double p) const;
  const StrengthTable& table() const { return table_; }
  double min_pressure() const { return table_.pressure.front(); }
  double max_pressure() const { return table_.pressure.back(); }
  /// Pressures where the law jumps (listed twice in the table).
  std::vector<double> jumps() const;

 private:
  double eval(const std::vector<double>& column, double p) const;
  StrengthTable table_;
  OutsideTable outside_;
  struct Piece;  // one continuous stretch, interpolated by GSL
  static std::vector<std::shared_ptr<const Piece>> split(const std::vector<double>& p, const std::vector<double>& v);
  std::vector<std::shared_ptr<const Piece>> pieces_max_, pieces_dyn_;
};

}  // namespace wearscale::materials
