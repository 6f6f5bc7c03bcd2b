#pragma once
// The friction law of an interface (Appendix A.1): the largest tangential
// traction p_T,max a contact point can carry before it slides,
//   Coulomb  p_T,max = μ p_N     (A.2)   macro/mesoscale contact,
//   Tresca   p_T,max = σ_m,T     (A.3)   nanoscale (asperity-level) contact,
// and p_T,max = 0 out of contact (p_N = 0) for both.
#include <string>

namespace wearscale::bem {

class FrictionLaw {
 public:
  enum class Kind { Coulomb, Tresca };

  /// InputError unless μ ≥ 0 and finite (μ = 0 is frictionless).
  static FrictionLaw coulomb(double coefficient);
  /// InputError unless σ_m,T ≥ 0 and finite [Pa].
  static FrictionLaw tresca(double shear_strength);

  Kind kind() const { return kind_; }
  /// μ (Coulomb) or σ_m,T (Tresca).
  double parameter() const { return parameter_; }
  /// p_T,max at a point carrying the normal traction p_N   (A.2), (A.3)
  double max_tangential(double p_normal) const {
    if (!(p_normal > 0.0)) return 0.0;
    return kind_ == Kind::Coulomb ? parameter_ * p_normal : parameter_;
  }
  /// "Coulomb (μ = 0.5)" / "Tresca (σ_m,T = 2.5e+08 Pa)".
  std::string to_string() const;

 private:
  FrictionLaw(Kind kind, double parameter) : kind_(kind), parameter_(parameter) {}
  Kind kind_;
  double parameter_;
};

}  // namespace wearscale::bem
