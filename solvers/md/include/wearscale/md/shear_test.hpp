#pragma once
// The MD shear test of §9.3.1 (Figs 9.12–9.18): a block of a material between
// two rigid walls, Langevin layers at 300 K next to the walls, a normal
// pressure and a shear velocity imposed on the top wall, periodic laterally.
// The tangential force on the top wall against its displacement gives the
// peak and the dynamic shear strength. The material is any with an
// interatomic model (materials/interatomic_model.hpp): a crystal cut with
// (001) faces against the walls, or an amorphous solid melt-quenched from it
// (Si: Stillinger–Weber diamond; SiO2: Vashishta, quenched from β-cristobalite).
//
// ShearTestSpec holds every input in SI; the two presets are `smoke` (small
// boxes, 100 m/s, seconds to a minute per pressure) and `thesis` (the thesis'
// 10 nm boxes at 10 m/s: hours per pressure point on two cores, a long job).
// The deck functions return LAMMPS input text generated here.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "wearscale/materials/interatomic_model.hpp"

namespace wearscale::md {

/// Melt–quench of an amorphous sample from its crystal (§2.1.3, after Luo et
/// al. 2016 for SiO2): hold at each temperature, cool linearly between holds,
/// Berendsen barostat at `pressure`, or at the crystal's volume throughout
/// (`constant_volume`: a set density, e.g. amorphous carbon).
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
  bool constant_volume = false;      ///< no barostat: the crystal's volume (set by its lattice constant)
};

struct ShearTestSpec {
  std::string preset;                ///< "smoke", "thesis" (or "custom")
  std::string material;              ///< its name ("Si", "Cu"): messages, provenance, the deck's header
  materials::InteratomicModel model; ///< potential, elements, masses, structure, lattice constant, amorphous or not
  std::vector<double> pressures;     ///< normal pressures p_N, increasing, ≥ 0 [Pa]
  double lateral_size = 0.0;         ///< box edge in x and y, rounded to whole cells [m]
  double height = 0.0;               ///< box height in z, rounded to whole cells [m]
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
  QuenchSchedule quench;             ///< amorphous samples only
  double modulus_strain = 0.1;       ///< the elastic shear modulus: slope of τ over strains up to this (a least-squares line through the elastic start, averaging the wall's elastic waves)
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

/// The presets, `smoke` and `thesis`, for `material` with `model` (checked:
/// materials::validate). InputError for another preset name.
ShearTestSpec preset_spec(const std::string& material, const materials::InteratomicModel& model,
                          const std::string& preset);
/// The same for a built-in material with its model ("Si", "SiO2"); InputError for another name.
ShearTestSpec preset_spec(const std::string& material, const std::string& preset);

/// Checks ranges and consistency (the model, window inside (0, strain_end],
/// walls and layers thinner than half the box, pressures increasing); InputError.
void validate(const ShearTestSpec& spec);

/// File names the decks use inside a run folder.
struct DeckFiles {
  std::string potential;                          ///< potential file name (copied/written into the run folder)
  std::string quenched_sample = "quenched.data";  ///< amorphous: write_data of the quench, read_data of the tests
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
std::string run_potential_name(const materials::InteratomicModel& model);

/// Deck lines of a model: `pair_style`, `pair_coeff` (naming `potential_file`
/// in the run folder) and a `mass` line per type (after pair_coeff, whose
/// eam styles set the file's masses: the declared ones win).
std::string pair_lines(const materials::InteratomicModel& model, const std::string& potential_file);
/// Deck lines that build a crystal of `cells` × `cells` × `z_cells` cubic cells
/// (lattice, region, create_box, create_atoms with the basis types), x = [100],
/// y = [010], z = [001].
std::string crystal_lines(const materials::InteratomicModel& model, long cells, long z_cells);

/// The LAMMPS deck of the shear test at normal pressure `pressure` [Pa].
std::string shear_deck(const ShearTestSpec& spec, double pressure, const DeckFiles& files);

/// The LAMMPS deck of the melt–quench (crystal → amorphous), ending with
/// write_data of the sample. InputError for a crystalline model.
std::string quench_deck(const ShearTestSpec& spec, const DeckFiles& files);

}  // namespace wearscale::md
