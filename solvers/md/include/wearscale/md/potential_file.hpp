#pragma once
// The interatomic potential file a LAMMPS run reads, as text: the installed
// file (Debian: /usr/share/lammps/potentials) read once, and for Vashishta
// silica a copy whose two-body cutoff r_c is rewritten (the thesis uses
// r_c = 8 Å, §2.1.3, after Luo et al. 2016; the Debian file has 10 Å).
#include <filesystem>
#include <string>

namespace wearscale::md {

/// The folder holding LAMMPS' potential files: $LAMMPS_POTENTIALS if set,
/// else /usr/share/lammps/potentials.
std::filesystem::path lammps_potentials_dir();

/// `name` as given if it is a path to an existing file, else the file of that
/// name in lammps_potentials_dir(). InputError naming both places if neither
/// exists (with the package to install).
std::filesystem::path find_potential_file(const std::filesystem::path& name);

/// The text of a file; InputError if it cannot be read.
std::string read_text_file(const std::filesystem::path& file);

/// A Vashishta potential file with the two-body cutoff r_c of every entry set
/// to `cutoff_angstrom`. The file format is LAMMPS' (pair_style vashishta):
/// entries of 17 fields, `el1 el2 el3 H eta Zi Zj lambda1 D lambda4 W rc B
/// gamma r0 C cos(theta)`, '#' comments, free line breaks; only entries
/// whose rc is non-zero are changed (r0, the three-body cutoff, is kept).
/// A header comment records the original file and the change. InputError
/// if the text is not a Vashishta file (field count, non-numbers).
std::string vashishta_with_cutoff(const std::string& text, double cutoff_angstrom, const std::string& origin);

}  // namespace wearscale::md
