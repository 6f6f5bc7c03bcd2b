#include "wearscale/bem/friction_law.hpp"

#include <cmath>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::bem {

FrictionLaw FrictionLaw::coulomb(double mu) {
  if (!(mu >= 0.0) || !std::isfinite(mu))
    throw InputError(fmt::format("Coulomb friction: coefficient μ = {} is not allowed; allowed: μ ≥ 0", mu));
  return {Kind::Coulomb, mu};
}

FrictionLaw FrictionLaw::tresca(double sigma) {
  if (!(sigma >= 0.0) || !std::isfinite(sigma))
    throw InputError(
        fmt::format("Tresca friction: shear strength σ_m,T = {} Pa is not allowed; allowed: σ_m,T ≥ 0", sigma));
  return {Kind::Tresca, sigma};
}

std::string FrictionLaw::to_string() const {
  return kind_ == Kind::Coulomb ? fmt::format("Coulomb (μ = {:g})", parameter_)
                                : fmt::format("Tresca (σ_m,T = {:g} Pa)", parameter_);
}

}  // namespace wearscale::bem
