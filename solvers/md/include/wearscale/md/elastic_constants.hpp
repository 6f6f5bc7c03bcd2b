#pragma once
// The elastic stiffness of an MD sample at 0 K by finite strains, and the
// moduli the shear test checks with it. A LAMMPS deck minimises the sample's
// energy (atoms relaxed, so the internal relaxation of a diamond lattice is
// included), then for each of the six Voigt strains at +δ and −δ restores
// that state, strains the box (x, y, z scale; yz, xz, xy tilt), minimises
// the atoms again and prints the pressure tensor; C_ij is the central
// difference of the stress σ = −P over the strain.
//
// Two samples: the potential's ideal lattice relaxed to zero stress (the
// reference: the potential's own elastic constants), and the sample as the
// shear test builds it (its declared lattice constant, box not relaxed, or
// the melt-quenched solid relaxed to zero stress).
#include <array>
#include <string>
#include <string_view>

#include "wearscale/materials/interatomic_model.hpp"

namespace wearscale::md {

/// C_ij in Pa, Voigt order xx yy zz yz xz xy, engineering shear strains.
using Stiffness = std::array<std::array<double, 6>, 6>;

/// What the shear test compares: for a crystal the directional moduli of the
/// shear geometry (z = [001] normal to the walls, shear xz), for an amorphous
/// solid the isotropic (Voigt–Reuss–Hill) ones.
struct ElasticModuli {
  double young_z = 0.0;      ///< E along z = 1/S33 [Pa]
  double poisson_zx = 0.0;   ///< ν_zx = −S13/S33 (contraction along x under stress along z)
  double shear_xz = 0.0;     ///< G_xz = 1/S55 [Pa], the shear of the shear test
  double bulk = 0.0;         ///< Hill bulk modulus [Pa]
  double shear = 0.0;        ///< Hill shear modulus [Pa]
  double young = 0.0;        ///< isotropic E = 9KG/(3K+G) [Pa]
  double poisson = 0.0;      ///< isotropic ν = (3K−2G)/(2(3K+G))
  double min_eigenvalue = 0.0;  ///< of C (symmetrised): > 0 for a mechanically stable solid (Born) [Pa]
  bool stable() const { return min_eigenvalue > 0.0; }
};

/// The moduli of C (GSL LU inverse, symmetric eigenvalues). NumericalError for a singular C.
ElasticModuli elastic_moduli(const Stiffness& c);

/// C of a cubic crystal from C11, C12, C44.
Stiffness cubic_stiffness(double c11, double c12, double c44);

/// The sample of a finite-strain deck.
struct ElasticSample {
  long cells = 1, z_cells = 1;   ///< crystal cells in x (= y) and z (ignored with a data file)
  std::string data_file;         ///< read_data this file instead of building the crystal (amorphous)
  bool relax_box = false;        ///< minimise the box to zero stress first
};

/// File names and the strain of the deck.
struct ElasticDeckFiles {
  std::string potential;             ///< potential file in the run folder
  std::string output = "elastic.txt";///< rows "k j sign pxx pyy pzz pyz pxz pxy lx ly lz" (bar, Å)
  std::string sample = "sample.txt"; ///< "atoms N", "completed yes"
  std::string restart = "unstrained.restart";
};

/// The LAMMPS deck (units metal) computing C_ij of `sample` with `model`, strain ±`strain`.
std::string elastic_deck(const materials::InteratomicModel& model, const ElasticSample& sample,
                         const ElasticDeckFiles& files, double strain, const std::string& what);

/// The unstrained state and C of a deck's output file.
struct ElasticResult {
  Stiffness c{};
  std::array<double, 6> stress0{};  ///< stress of the unstrained state [Pa] (compressive < 0)
  double lx = 0.0, ly = 0.0, lz = 0.0;  ///< its box [m]
};
/// Parses the output (13 rows, k = 0…12). NumericalError naming `source` and
/// the line for a missing row, a non-number or a non-finite value.
ElasticResult parse_elastic(std::string_view text, double strain, const std::string& source);

}  // namespace wearscale::md
