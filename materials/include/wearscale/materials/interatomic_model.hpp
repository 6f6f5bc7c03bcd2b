#pragma once
// The interatomic model of a material, as the MD shear test of §9.3.1 needs
// it: a LAMMPS pair style and its potential file, the element and atomic mass
// of each atom type, and how a sample is prepared — cut from a crystal of a
// given structure and lattice constant, or melt-quenched from that crystal
// into an amorphous solid (§2.1.3). Built in for Si (Stillinger–Weber) and
// SiO2 (Vashishta); a case declares others in [materials.define.<name>.interatomic].
//
// Every text here ends up in a LAMMPS input deck, so validate() holds each to
// a grammar that cannot change the deck's meaning (no spaces, quotes, '$',
// '#', '&'): element names, the potential file's name (the deck names a copy
// of the file in the run folder, never the user's path) and the pair style,
// which must be one of pair_styles().
#include <filesystem>
#include <string>
#include <vector>

namespace wearscale::materials {

/// The crystal a sample is cut from, x = [100], y = [010], z = [001] of its cubic cell.
enum class Structure {
  Fcc,           ///< one atom type
  Bcc,           ///< one atom type
  SimpleCubic,   ///< one atom type
  Diamond,       ///< one atom type (Si, Ge, C)
  Zincblende,    ///< two types: type 1 on the fcc sites, type 2 on the others (SiC, GaN)
  Cristobalite,  ///< two types: β-cristobalite AB2, A on the diamond sites, B mid-bond (SiO2)
};
std::string to_string(Structure s);
/// "fcc", "bcc", "sc", "diamond", "zincblende", "cristobalite"; InputError otherwise.
Structure structure_from_string(const std::string& name);
std::vector<std::string> structure_names();
/// Atom types of a structure (1 or 2).
int structure_types(Structure s);
/// Atoms per cubic cell of a structure (fcc 4, bcc 2, sc 1, diamond and zincblende 8, cristobalite 24).
int structure_atoms_per_cell(Structure s);

/// Published elastic constants of an amorphous sample made with the potential
/// (an amorphous sample has no ideal lattice to compute them on): the isotropic
/// Young's modulus and Poisson's ratio, and where they come from.
struct ElasticReference {
  double young = 0.0;    ///< [Pa]
  double poisson = 0.0;
  std::string source;    ///< citation
  bool given() const { return young > 0.0; }
};

struct InteratomicModel {
  std::string pair_style;             ///< one of pair_styles(): "eam/alloy", "sw", "tersoff", ...
  std::filesystem::path potential;    ///< file: a name in LAMMPS' potentials folder, or a path
  std::vector<std::string> elements;  ///< element of each atom type, as the potential file names it
  std::vector<double> masses;         ///< atomic mass of each type [g/mol]
  Structure structure = Structure::Fcc;
  double lattice_constant = 0.0;      ///< edge of the cubic cell [m]
  bool amorphous = false;             ///< melt–quench the crystal before the tests
  double cutoff = 0.0;                ///< pair_style vashishta only: two-body r_c written into the file [m]; 0 = the file's
  ElasticReference reference;         ///< required for an amorphous sample
  std::vector<double> quench_temperatures;  ///< amorphous: hold temperatures, melt first [K]; empty = the protocol's
  bool quench_constant_volume = false;      ///< amorphous: quench at the crystal's volume (a set density), no barostat
  std::string source;                 ///< citation of the potential (provenance)
};

/// The pair styles whose `pair_coeff * * FILE ELEMENTS...` (or, for `eam`,
/// `pair_coeff 1 1 FILE`) the decks write: one potential file, no extra argument.
const std::vector<std::string>& pair_styles();

/// Whether `name` is a safe element name ([A-Za-z][A-Za-z0-9_]{0,15}) and
/// `file` a safe file name ([A-Za-z0-9][A-Za-z0-9._+-]{0,127}) for a deck.
bool safe_element_name(const std::string& name);
bool safe_file_name(const std::string& name);

/// Checks the grammar above, the pair style, one element and mass per type of
/// the structure (one element only for `eam`), masses in (0, 1000] g/mol, a
/// lattice constant in (1, 30] Å, a cutoff for vashishta only, and a published
/// reference for an amorphous sample (quench temperatures decreasing, for an amorphous one only). InputError naming `what` (the material)
/// and the field.
void validate(const InteratomicModel& model, const std::string& what);

/// Stillinger–Weber Si on the diamond lattice (§2.1.3, thesis Fig. 9.12).
InteratomicModel silicon_model();
/// Vashishta 1990 SiO2 at r_c = 8 Å, melt-quenched from β-cristobalite (§2.1.3).
InteratomicModel silica_model();

}  // namespace wearscale::materials
