#pragma once
// Material records: elastic constants, density, surface energy and ideal
// strengths (Table 2.1, Table 6.5), built in for Si and SiO2 or defined by a
// case ([materials.define.<name>]).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/materials/interatomic_model.hpp"

namespace wearscale::materials {

struct Material {
  std::string name;
  double young = 0.0;             ///< E [Pa]
  double poisson = 0.0;           ///< ν
  double density = 0.0;           ///< ρ [kg/m³]
  double surface_energy = 0.0;    ///< γ [J/m²]
  double tensile_strength = 0.0;  ///< ideal tensile strength σ_m,N [Pa]
  double shear_strength = 0.0;    ///< ideal shear strength σ_m,T [Pa]
  std::optional<double> restitution;  ///< η, the DEM restitution coefficient (Table 6.5)
  std::optional<InteratomicModel> interatomic;  ///< for the MD shear test (§9.3.1), if the material has one
  std::string source;             ///< where the numbers come from

  double shear_modulus() const { return young / (2.0 * (1.0 + poisson)); }  // G = E / 2(1+ν)
};

/// Si (crystalline, direction-averaged) of Table 2.1.
Material silicon();
/// Amorphous SiO2 of Table 2.1 / Table 6.5.
Material silica();

/// 1/E* = (1−ν1²)/E1 + (1−ν2²)/E2   (1.12)
double effective_modulus(const Material& a, const Material& b);

/// The geometric factor of the critical junction size d* = c·γG/σ² (with σ
/// the junction's shear strength) for the configuration it was derived for.
enum class JunctionGeometry {
  FlatCircular,        ///< c = 12π/(2−ν): sheared flat circular micro-contact (4.35)
  CollidingAsperities, ///< c = 12: cold-welded colliding asperities, Aghababaei et al. (8.3)
  DemCylinder,         ///< c = 32: the cylindrical DEM junction of §6.3 (6.65)
};
double geometric_factor(JunctionGeometry geometry, double poisson);
/// d* = c γ G / σ_j²   (4.35), (6.65), (8.3)
double critical_size(const Material& m, double junction_strength, JunctionGeometry geometry);

/// Built-in materials plus those a case defines (io/material_definitions.hpp). Lookups of unknown names are
/// InputError listing the known ones.
class MaterialLibrary {
 public:
  /// Si and SiO2.
  MaterialLibrary();
  void add(Material m);
  const Material& get(const std::string& name) const;
  bool contains(const std::string& name) const { return by_name_.count(name) != 0; }
  std::vector<std::string> names() const;

 private:
  std::map<std::string, Material> by_name_;
};

}  // namespace wearscale::materials
