// The LAMMPS decks of the §9.3.1 shear test and the SiO2 melt-quench, and the
// presets (the [md] case keys: tests/coupling/test_shear_test_keys.cpp).
#include <gtest/gtest.h>

#include "hostile_seed.hpp"
#include "md_test_support.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/md/shear_test.hpp"

using namespace wearscale;
using namespace wearscale::md;
using md_test::has_line;

TEST(ShearDeck, SiHasSwPotentialWallsLoadAndVelocity) {
  ShearTestSpec s = preset_spec("Si", "smoke");
  s.pressures = {0.0, 10e9};
  DeckFiles f;
  f.potential = run_potential_name(s.model);
  const std::string d = shear_deck(s, 10e9, f);
  EXPECT_TRUE(has_line(d, "pair_style sw"));
  EXPECT_TRUE(has_line(d, "pair_coeff * * Si.sw Si"));
  EXPECT_TRUE(has_line(d, "boundary p p s")) << "periodic in x and y, free z";
  EXPECT_TRUE(has_line(d, "lattice diamond 5.431 orient x 1 0 0 orient y 0 1 0 orient z 0 0 1"));
  EXPECT_TRUE(has_line(d, "region box block 0 4 0 4 0 4")) << "2.2 nm = 4 cells of 5.431 Å";
  // Imposed pressure: 10 GPa = 1e5 bar spread over the top wall atoms, along -z.
  EXPECT_TRUE(has_line(d, "variable p_bar equal 100000"));
  EXPECT_TRUE(has_line(d, "variable load_per_atom equal -v_p_bar*lx*ly/count(top)/1602176.634"));
  EXPECT_TRUE(has_line(d, "fix load_top top aveforce NULL NULL ${load}"));
  // Imposed shear velocity: 100 m/s = 1 Å/ps along x, in box units.
  EXPECT_TRUE(has_line(d, "velocity top set 1 0.0 NULL units box"));
  EXPECT_TRUE(has_line(d, "fix hold_top top setforce 0.0 0.0 NULL"));
  // Langevin layers thermostat only y and z (x, the sliding direction, is the bias).
  EXPECT_TRUE(has_line(d, "compute t_layers layers temp/partial 0 1 1"));
  EXPECT_TRUE(has_line(d, "fix thermostat layers langevin 300 300 0.01 2"));
  EXPECT_TRUE(has_line(d, "fix_modify thermostat temp t_layers"));
  EXPECT_TRUE(has_line(d, "timestep 0.001"));
  EXPECT_TRUE(has_line(d, "fix curve all ave/time 1 100 100 v_strain v_tau v_p_n v_h c_t_mobile file shear.dat"));
  // The run ends at the final strain, whatever the height does meanwhile.
  EXPECT_TRUE(has_line(d, "fix stop all halt 100 v_strain > 0.6 error continue"));
  // The strain uses the height measured from atom positions, not the box.
  EXPECT_TRUE(has_line(d, "variable h equal xcm(top,z)-xcm(bottom,z)"));
  EXPECT_TRUE(has_line(d, "print \"h_gap_A $(bound(top,zmin)-bound(bottom,zmax):%.6f)\" append sample.txt screen no"));
}

TEST(ShearDeck, SiO2ReadsQuenchedSampleWithVashishtaAt8Angstrom) {
  ShearTestSpec s = preset_spec("SiO2", "smoke");
  s.pressures = {0.0, 20e9};
  EXPECT_DOUBLE_EQ(s.model.cutoff, 8e-10);
  DeckFiles f;
  f.potential = run_potential_name(s.model);
  EXPECT_EQ(f.potential, "SiO.1990.vashishta.rc8");
  const std::string d = shear_deck(s, 20e9, f);
  EXPECT_TRUE(has_line(d, "read_data quenched.data"));
  EXPECT_TRUE(has_line(d, "change_box all boundary p p s"));
  EXPECT_TRUE(has_line(d, "pair_style vashishta"));
  EXPECT_TRUE(has_line(d, "pair_coeff * * SiO.1990.vashishta.rc8 Si O"));
  EXPECT_TRUE(has_line(d, "variable p_bar equal 200000"));
  EXPECT_TRUE(has_line(d, "compute t_layers layers temp/partial 0 1 1"));
  EXPECT_FALSE(has_line(d, "velocity mobile create")) << "velocities come from the quench";
}

TEST(QuenchDeck, BetaCristobaliteThroughTheScheduleToWriteData) {
  ShearTestSpec s = preset_spec("SiO2", "smoke");
  s.pressures = {0.0};
  DeckFiles f;
  f.potential = run_potential_name(s.model);
  const std::string d = quench_deck(s, f);
  EXPECT_TRUE(has_line(d, "pair_style vashishta"));
  EXPECT_TRUE(has_line(d, "region box block 0 4 0 4 0 4")) << "2.8 nm = 4 cells of 7.16 Å: 1536 atoms";
  EXPECT_TRUE(has_line(d, "create_box 2 box"));
  std::size_t basis = 0;
  for (std::size_t p = d.find("basis "); p != std::string::npos; p = d.find("basis ", p + 1)) ++basis;
  EXPECT_EQ(basis, 48u) << "24 basis atoms, declared and typed";
  EXPECT_TRUE(has_line(d, "fix barostat all press/berendsen iso 0 0 1 modulus 360000"));
  EXPECT_TRUE(has_line(d, "fix thermostat all langevin 5000 5000 0.1"));
  EXPECT_TRUE(has_line(d, "# cool 500 K -> 300 K at 100 K/ps"));
  EXPECT_TRUE(has_line(d, "fix thermostat all langevin 300 300 0.1"));
  EXPECT_TRUE(has_line(d, "write_data quenched.data nocoeff"));
  EXPECT_THROW(quench_deck(preset_spec("Si", "smoke"), f), InputError);
}

TEST(ShearPresets, ThesisIsTheThesisSetup) {
  const ShearTestSpec t = preset_spec("Si", "thesis");
  EXPECT_DOUBLE_EQ(t.shear_velocity, 10.0);
  EXPECT_EQ(t.lateral_cells(), 18);  // 9.8 nm
  EXPECT_DOUBLE_EQ(t.strain_end, 0.5);
  const ShearTestSpec q = preset_spec("SiO2", "thesis");
  EXPECT_DOUBLE_EQ(q.quench.timestep, 0.5e-15);
  EXPECT_NEAR(q.quench.hold_time, 45e-12, 1e-20);
  EXPECT_NEAR(q.quench.final_cooling_rate, 13e12, 1.0);
  EXPECT_THROW(preset_spec("Si", "huge"), InputError);
}

TEST(ShearSpec, FingerprintChangesWithEveryRunInput) {
  ShearTestSpec a = preset_spec("SiO2", "smoke");
  ShearTestSpec b = a;
  b.quench.hold_time *= 2;
  EXPECT_NE(a.fingerprint(), b.fingerprint());
  b = a;
  b.seed = 2;
  EXPECT_NE(a.fingerprint(), b.fingerprint());
  b = a;
  b.pressures = {1e9};  // pressures live in each run's deck, not in the fingerprint
  EXPECT_EQ(a.fingerprint(), b.fingerprint());
}

// No file name is LAMMPS code: a potential file whose name holds a newline and a
// `shell` command, `$`, `#` or quotes is copied into the run folder under a deck
// word, and a deck refuses any other word it is handed.
TEST(ShearDeck, AFileNameIsNeverLammpsCode) {
  ShearTestSpec s = preset_spec("Si", "smoke");
  s.pressures = {0.0, 10e9};
  for (const std::string hostile : {"x\nshell touch PWNED\n.sw", "a b.sw", "${x}.sw", "#.sw", "'q'.sw", "-in.sw",
                                    ".hidden", "x&\nshell rm -rf .sw"}) {
    s.model.potential = "/somewhere/" + hostile;
    const std::string name = run_potential_name(s.model);
    EXPECT_TRUE(is_deck_word(name)) << name;
    EXPECT_EQ(name.rfind("potential_", 0), 0u) << name;
    DeckFiles f;
    f.potential = name;
    const std::string d = shear_deck(s, 10e9, f);
    EXPECT_TRUE(has_line(d, "pair_coeff * * " + name + " Si"));
    EXPECT_EQ(d.find("\nshell"), std::string::npos) << "the name's `shell` is a word of it, never a command";
    f.potential = hostile;  // handed a word that is not one: refused, never written
    EXPECT_THROW((void)shear_deck(s, 10e9, f), std::logic_error) << hostile;
  }
  s.model.potential = "/usr/share/lammps/potentials/Si.sw";
  EXPECT_EQ(run_potential_name(s.model), "Si.sw") << "a plain name is kept (the cache keys of shipped potentials stand)";
}

// The class's generator: potential file names made of the characters of LAMMPS'
// and shells' syntax, a new set each run (WEARSCALE_HOSTILE_SEED replays one).
TEST(ShearDeck, GeneratedHostileFileNamesAreNeverLammpsCode) {
  auto rng = hostile_generator("lammps-deck-words");
  const std::vector<std::string> parts{"\n", "shell touch PWNED", "$", "${x}", "#", "'", "\"", "&", " ", "-",
                                       ".",  "\\",  ";",    "`", "v_", "Si", "sw", "/"};
  ShearTestSpec s = preset_spec("Si", "smoke");
  s.pressures = {0.0, 10e9};
  for (int k = 0; k < 200; ++k) {
    std::string hostile;
    const int n = std::uniform_int_distribution<int>(1, 8)(rng);
    for (int p = 0; p < n; ++p) hostile += pick(rng, parts);
    if (hostile.ends_with("/")) hostile += "x";
    SCOPED_TRACE(hostile);
    s.model.potential = "/somewhere/" + hostile;
    const std::string name = run_potential_name(s.model);
    ASSERT_TRUE(is_deck_word(name)) << name;
    DeckFiles f;
    f.potential = name;
    const std::string d = shear_deck(s, 10e9, f);
    EXPECT_TRUE(has_line(d, "pair_coeff * * " + name + " Si"));
    EXPECT_EQ(d.find("\nshell"), std::string::npos) << "no command of the name starts a line";
    f.potential = std::filesystem::path(hostile).filename().string();
    if (!is_deck_word(f.potential)) {
      EXPECT_THROW((void)shear_deck(s, 10e9, f), std::logic_error);
    }
  }
}

namespace {
materials::InteratomicModel nickel() {
  materials::InteratomicModel m;
  m.pair_style = "eam";
  m.potential = "Ni_u3.eam";
  m.elements = {"Ni"};
  m.masses = {58.6934};
  m.structure = materials::Structure::Fcc;
  m.lattice_constant = 3.52e-10;
  return m;
}
}  // namespace

TEST(ShearDeck, AnyCrystalWithItsPotentialElementsAndMasses) {
  ShearTestSpec s = preset_spec("Ni", nickel(), "smoke");
  s.pressures = {0.0};
  DeckFiles f;
  f.potential = run_potential_name(s.model);
  const std::string d = shear_deck(s, 0.0, f);
  EXPECT_TRUE(has_line(d, "lattice fcc 3.52 orient x 1 0 0 orient y 0 1 0 orient z 0 0 1"));
  EXPECT_TRUE(has_line(d, "region box block 0 6 0 6 0 6")) << "2.2 nm = 6 cells of 3.52 Å";
  EXPECT_TRUE(has_line(d, "pair_style eam"));
  EXPECT_TRUE(has_line(d, "pair_coeff 1 1 Ni_u3.eam")) << "funcfl: one file per type, no element map";
  EXPECT_TRUE(has_line(d, "mass 1 58.6934"));
  EXPECT_LT(d.find("pair_coeff"), d.find("mass 1")) << "the declared mass after the file's";
  EXPECT_TRUE(has_line(d, "velocity mobile create 600"));
  EXPECT_EQ(s.ranks, 1);
  // Two elements on a zincblende lattice: the second type on the displaced sites.
  materials::InteratomicModel sic = nickel();
  sic.pair_style = "tersoff";
  sic.potential = "SiC.tersoff";
  sic.elements = {"Si", "C"};
  sic.masses = {28.0855, 12.011};
  sic.structure = materials::Structure::Zincblende;
  sic.lattice_constant = 4.36e-10;
  ShearTestSpec z = preset_spec("SiC", sic, "smoke");
  const std::string dz = shear_deck(z, 0.0, {"SiC.tersoff"});
  EXPECT_TRUE(has_line(dz, "create_box 2 box"));
  EXPECT_TRUE(has_line(dz, "create_atoms 1 box basis 5 2 basis 6 2 basis 7 2 basis 8 2"));
  EXPECT_TRUE(has_line(dz, "pair_coeff * * SiC.tersoff Si C"));
  EXPECT_TRUE(has_line(dz, "mass 2 12.011"));
}

TEST(ShearDeck, AnAmorphousMaterialIsQuenchedFromItsCrystalAtItsOwnSchedule) {
  materials::InteratomicModel c = nickel();
  c.pair_style = "tersoff";
  c.potential = "SiC.tersoff";
  c.elements = {"C"};
  c.masses = {12.011};
  c.structure = materials::Structure::Diamond;
  c.lattice_constant = 3.76e-10;
  c.amorphous = true;
  c.quench_temperatures = {6000, 300};
  c.quench_constant_volume = true;
  c.reference = {300e9, 0.2, "a reference"};
  ShearTestSpec s = preset_spec("aC", c, "smoke");
  s.pressures = {0.0};
  EXPECT_EQ(s.quench.temperatures, (std::vector<double>{6000, 300}));
  const std::string q = quench_deck(s, {"SiC.tersoff"});
  EXPECT_TRUE(has_line(q, "lattice diamond 3.76"));
  EXPECT_FALSE(has_line(q, "fix barostat")) << "constant volume: the crystal's density";
  EXPECT_TRUE(has_line(q, "fix thermostat all langevin 6000 6000 0.1"));
  EXPECT_TRUE(has_line(q, "write_data quenched.data nocoeff"));
  const std::string d = shear_deck(s, 0.0, {"SiC.tersoff"});
  EXPECT_TRUE(has_line(d, "read_data quenched.data"));
  EXPECT_TRUE(has_line(d, "pair_coeff * * SiC.tersoff C"));
}

TEST(InteratomicModel, TextThatWouldChangeADeckIsRefused) {
  auto refused = [](auto change) {
    materials::InteratomicModel m = nickel();
    change(m);
    EXPECT_THROW(preset_spec("X", m, "smoke"), InputError);
  };
  refused([](auto& m) { m.elements = {"Ni\nshell rm -rf /"}; });
  refused([](auto& m) { m.elements = {"${x}"}; });
  refused([](auto& m) { m.potential = "/tmp/my pot.eam"; });
  refused([](auto& m) { m.potential = "Ni$u3.eam"; });
  refused([](auto& m) { m.pair_style = "eam\nshell ls"; });
  refused([](auto& m) { m.pair_style = "meam"; });
  refused([](auto& m) { m.elements = {"Ni", "Cu"}; });   // fcc has one type
  refused([](auto& m) { m.masses = {0.0}; });
  refused([](auto& m) { m.lattice_constant = 3.52; });   // metres: 3.52 m is not a lattice constant
  refused([](auto& m) { m.cutoff = 8e-10; });            // vashishta only
  refused([](auto& m) { m.amorphous = true; });          // no published reference
  EXPECT_NO_THROW(preset_spec("Ni", nickel(), "smoke"));
  EXPECT_TRUE(materials::safe_file_name("Cu_mishin1.eam.alloy"));
  EXPECT_FALSE(materials::safe_file_name("-x"));
  EXPECT_FALSE(materials::safe_file_name("a&b"));
}
