#include "wearscale/materials/strength_law.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_interp.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::materials {

// GSL's linear interpolation over one stretch of strictly increasing pressures.
struct StrengthLaw::Piece {
  std::vector<double> x, y;
  gsl_interp* interp = nullptr;
  Piece(std::vector<double> px, std::vector<double> py) : x(std::move(px)), y(std::move(py)) {
    interp = gsl_interp_alloc(gsl_interp_linear, x.size());
    gsl_interp_init(interp, x.data(), y.data(), x.size());
  }
  ~Piece() { gsl_interp_free(interp); }
  Piece(const Piece&) = delete;
  Piece& operator=(const Piece&) = delete;
  double operator()(double p) const {
    double v = 0.0;
    gsl_interp_eval_e(interp, x.data(), y.data(), std::clamp(p, x.front(), x.back()), nullptr, &v);
    return v;
  }
};

StrengthLaw::StrengthLaw(StrengthTable table, OutsideTable outside) : table_(std::move(table)), outside_(outside) {
  validate(table_);
  pieces_max_ = split(table_.pressure, table_.sigma_max);
  pieces_dyn_ = split(table_.pressure, table_.sigma_dyn);
}

std::vector<std::shared_ptr<const StrengthLaw::Piece>> StrengthLaw::split(const std::vector<double>& p,
                                                                           const std::vector<double>& v) {
  std::vector<std::shared_ptr<const Piece>> out;
  std::size_t start = 0;
  for (std::size_t r = 1; r <= p.size(); ++r) {
    if (r < p.size() && p[r] != p[r - 1]) continue;
    std::vector<double> x(p.begin() + static_cast<long>(start), p.begin() + static_cast<long>(r));
    std::vector<double> y(v.begin() + static_cast<long>(start), v.begin() + static_cast<long>(r));
    out.push_back(std::make_shared<const Piece>(std::move(x), std::move(y)));  // ≥ 2 rows: validate()
    start = r;
  }
  return out;
}

StrengthLaw StrengthLaw::constant(const std::string& material, double value, double p_max, const std::string& source) {
  StrengthTable t;
  t.material = material;
  t.pressure = {0.0, p_max};
  t.sigma_max = {value, value};
  t.sigma_dyn = {value, value};
  t.provenance = {{"material", material}, {"source", source}};
  t.origin = source;
  return StrengthLaw(std::move(t), OutsideTable::Clamp);
}

std::vector<double> StrengthLaw::jumps() const {
  std::vector<double> out;
  for (std::size_t r = 1; r < table_.pressure.size(); ++r)
    if (table_.pressure[r] == table_.pressure[r - 1]) out.push_back(table_.pressure[r]);
  return out;
}

double StrengthLaw::eval(const std::vector<double>& column, double p) const {
  if (!std::isfinite(p)) throw NumericalError("materials/strength-law", 0, "pressure", fmt::format("{} is not finite", p));
  if (p < min_pressure() || p > max_pressure()) {
    if (outside_ == OutsideTable::Error)
      throw NumericalError("materials/strength-law", 0, "pressure",
                           fmt::format("{:g} GPa is outside the table {} ({} from {:g} to {:g} GPa); extend the table "
                                       "or allow clamping",
                                       p / 1e9, table_.origin, table_.material, min_pressure() / 1e9,
                                       max_pressure() / 1e9));
    p = std::clamp(p, min_pressure(), max_pressure());
  }
  const auto& pieces = &column == &table_.sigma_max ? pieces_max_ : pieces_dyn_;
  // The last piece starting at or below p (a jump belongs to the piece above it).
  std::size_t k = 0;
  while (k + 1 < pieces.size() && pieces[k + 1]->x.front() <= p) ++k;
  return (*pieces[k])(p);
}

double StrengthLaw::sigma_max(double p) const { return eval(table_.sigma_max, p); }
double StrengthLaw::sigma_dyn(double p) const { return eval(table_.sigma_dyn, p); }

}  // namespace wearscale::materials
