#pragma once
// The MD shear test of §9.3.1 (Figs 9.12–9.18): a block of Si (diamond
// lattice, (001) faces) or amorphous SiO2 between two rigid walls, Langevin
// layers at 300 K next to the walls, a normal pressure and a shear velocity
// imposed on the top wall, periodic laterally. The tangential force on the top
// wall against its displacement gives the peak and the dynamic shear strength.
//
// ShearTestSpec holds every input in SI; the two presets are `smoke` (small
// boxes, 100 m/s, seconds to a minute per pressure) and `thesis` (the thesis'
// 10 nm boxes at 10 m/s: hours per pressure point on two cores, a long job).
// The deck functions return LAMMPS input text generated here.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace wearscale::md {

enum class Material { Si, SiO2 };
std::string to_string(Material m);
/// "Si" or "SiO2"; InputError otherwise.
Material material_from_string(const std::string& name);

/// Melt–quench of SiO2 from β-cristobalite (§2.1.3, after Luo et al. 2016):
/// hold at each temperature, cool linearly between holds, barostat at `pressure`.
struct QuenchSchedule {
  std::vector<double> temperatures;  ///< hold temperatures in order, melt first, final last [K]
  double hold_time = 0.0;            ///< at each temperature [s]
  double cooling_rate = 0.0;         ///< between holds [K/s]
  double final_cooling_rate = 0.0;   ///< into the last temperature [K/s]
  double timestep = 0.0;             ///< [s]
  double pressure = 0.0;             ///< Berendsen barostat target [Pa]
  double barostat_damp = 0.0;        ///< [s]
  double bulk_modulus = 0.0;         ///< the barostat's compressibility guess [Pa]
  double thermostat_damp = 0.0;      ///< Langevin damping time of the quench [s]
};

struct ShearTestSpec {
  std::string preset;                ///< "smoke", "thesis" (or "custom")
  Material material = Material::Si;
  std::vector<double> pressures;     ///< normal pressures p_N, increasing, ≥ 0 [Pa]
  double lateral_size = 0.0;         ///< box edge in x and y, rounded to whole cells [m]
  double height = 0.0;               ///< box height in z, rounded to whole cells [m]
  double lattice_constant = 0.0;     ///< Si diamond / β-cristobalite cubic cell [m]
  double wall_thickness = 0.0;       ///< rigid walls at top and bottom [m]
  double thermostat_thickness = 0.0; ///< Langevin layers next to the walls [m]
  double shear_velocity = 0.0;       ///< of the top wall, along x [m/s]
  double temperature = 0.0;          ///< of the Langevin layers [K]
  double langevin_damp = 0.0;        ///< Langevin damping time [s]
  double timestep = 0.0;             ///< [s]
  double compression_time = 0.0;     ///< load applied, no shear, before shearing [s]
  double strain_end = 0.0;           ///< shear strain at which the run stops
  double window_begin = 0.0;         ///< σ_dyn = mean shear stress for strain in
  double window_end = 0.0;           ///<   [window_begin, window_end]
  long sample_steps = 0;             ///< steps averaged into one output row
  std::uint32_t seed = 1;            ///< base seed (velocities seed, Langevin seed+1, quench seed+2…)
  QuenchSchedule quench;             ///< SiO2 only
  std::filesystem::path potential;   ///< potential file (name in the LAMMPS potentials folder, or a path)
  double cutoff = 0.0;               ///< Vashishta two-body cutoff r_c [m]; 0 = as in the file (SW: a·σ)
  std::string lmp;                   ///< lmp executable; empty = search PATH
  int ranks = 1;                     ///< MPI ranks (mpirun) when > 1
  bool use_cache = true;             ///< reuse results of identical inputs
  std::filesystem::path cache_dir;   ///< empty = cache_folder("lammps")

  /// Cells of the lattice along x (= y) and z.
  long lateral_cells() const;
  long height_cells() const;
  /// Number of integration steps of a time (rounded, ≥ 1).
  long steps(double duration, double dt) const;
  /// Every input that changes a run (all but pressures, lmp, ranks' mpirun
  /// path and cache settings), one "key = value" per line, for the cache key.
  std::string fingerprint() const;
};

/// The presets: `smoke` and `thesis`. InputError for another name.
ShearTestSpec preset_spec(Material material, const std::string& preset);

/// Checks ranges and consistency (window inside (0, strain_end], walls and
/// layers thinner than half the box, pressures increasing); InputError.
void validate(const ShearTestSpec& spec);

/// File names the decks use inside a run folder.
struct DeckFiles {
  std::string potential;                          ///< potential file name (copied/written into the run folder)
  std::string quenched_sample = "quenched.data";  ///< SiO2: write_data of the quench, read_data of the shear test
  std::string curve = "shear.dat";                ///< fix ave/time rows: step strain tau pN h T
  std::string sample = "sample.txt";              ///< "key value" lines: atoms, box, wall counts, completion
};

/// Whether `word` may appear in a deck as it is: [A-Za-z0-9._+-] only, not
/// starting with '-' or '.', at most 200 characters. Every word of a deck that
/// wearscale did not write itself (file names, the preset) is one; the deck
/// functions refuse others (std::logic_error), so no input is LAMMPS code.
bool is_deck_word(const std::string& word);

/// The name of the potential file inside a run folder (the Vashishta copy with
/// its cutoff in the name, e.g. "SiO.1990.vashishta.rc8"): the user's file
/// name when it is a deck word, else that name with every other character
/// replaced by '_' after "potential_".
std::string run_potential_name(const ShearTestSpec& spec);

/// The LAMMPS deck of the shear test at normal pressure `pressure` [Pa].
std::string shear_deck(const ShearTestSpec& spec, double pressure, const DeckFiles& files);

/// The LAMMPS deck of the SiO2 melt–quench (β-cristobalite → amorphous),
/// ending with write_data of the sample. InputError for Si.
std::string quench_deck(const ShearTestSpec& spec, const DeckFiles& files);

}  // namespace wearscale::md
