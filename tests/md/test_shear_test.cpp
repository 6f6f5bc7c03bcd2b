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
  ShearTestSpec s = preset_spec(Material::Si, "smoke");
  s.pressures = {0.0, 10e9};
  DeckFiles f;
  f.potential = run_potential_name(s);
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
}

TEST(ShearDeck, SiO2ReadsQuenchedSampleWithVashishtaAt8Angstrom) {
  ShearTestSpec s = preset_spec(Material::SiO2, "smoke");
  s.pressures = {0.0, 20e9};
  EXPECT_DOUBLE_EQ(s.cutoff, 8e-10);
  DeckFiles f;
  f.potential = run_potential_name(s);
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
  ShearTestSpec s = preset_spec(Material::SiO2, "smoke");
  s.pressures = {0.0};
  DeckFiles f;
  f.potential = run_potential_name(s);
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
  EXPECT_THROW(quench_deck(preset_spec(Material::Si, "smoke"), f), InputError);
}

TEST(ShearPresets, ThesisIsTheThesisSetup) {
  const ShearTestSpec t = preset_spec(Material::Si, "thesis");
  EXPECT_DOUBLE_EQ(t.shear_velocity, 10.0);
  EXPECT_EQ(t.lateral_cells(), 18);  // 9.8 nm
  EXPECT_DOUBLE_EQ(t.strain_end, 0.5);
  const ShearTestSpec q = preset_spec(Material::SiO2, "thesis");
  EXPECT_DOUBLE_EQ(q.quench.timestep, 0.5e-15);
  EXPECT_NEAR(q.quench.hold_time, 45e-12, 1e-20);
  EXPECT_NEAR(q.quench.final_cooling_rate, 13e12, 1.0);
  EXPECT_THROW(preset_spec(Material::Si, "huge"), InputError);
}

TEST(ShearSpec, FingerprintChangesWithEveryRunInput) {
  ShearTestSpec a = preset_spec(Material::SiO2, "smoke");
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
  ShearTestSpec s = preset_spec(Material::Si, "smoke");
  s.pressures = {0.0, 10e9};
  for (const std::string hostile : {"x\nshell touch PWNED\n.sw", "a b.sw", "${x}.sw", "#.sw", "'q'.sw", "-in.sw",
                                    ".hidden", "x&\nshell rm -rf .sw"}) {
    s.potential = "/somewhere/" + hostile;
    const std::string name = run_potential_name(s);
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
  s.potential = "/usr/share/lammps/potentials/Si.sw";
  EXPECT_EQ(run_potential_name(s), "Si.sw") << "a plain name is kept (the cache keys of shipped potentials stand)";
}

// The class's generator: potential file names made of the characters of LAMMPS'
// and shells' syntax, a new set each run (WEARSCALE_HOSTILE_SEED replays one).
TEST(ShearDeck, GeneratedHostileFileNamesAreNeverLammpsCode) {
  auto rng = hostile_generator("lammps-deck-words");
  const std::vector<std::string> parts{"\n", "shell touch PWNED", "$", "${x}", "#", "'", "\"", "&", " ", "-",
                                       ".",  "\\",  ";",    "`", "v_", "Si", "sw", "/"};
  ShearTestSpec s = preset_spec(Material::Si, "smoke");
  s.pressures = {0.0, 10e9};
  for (int k = 0; k < 200; ++k) {
    std::string hostile;
    const int n = std::uniform_int_distribution<int>(1, 8)(rng);
    for (int p = 0; p < n; ++p) hostile += pick(rng, parts);
    if (hostile.ends_with("/")) hostile += "x";
    SCOPED_TRACE(hostile);
    s.potential = "/somewhere/" + hostile;
    const std::string name = run_potential_name(s);
    ASSERT_TRUE(is_deck_word(name)) << name;
    DeckFiles f;
    f.potential = name;
    const std::string d = shear_deck(s, 10e9, f);
    EXPECT_TRUE(has_line(d, "pair_coeff * * " + name + " Si"));
    EXPECT_EQ(d.find("\nshell"), std::string::npos) << "no command of the name starts a line";
    f.potential = std::filesystem::path(hostile).filename().string();
    if (!is_deck_word(f.potential)) EXPECT_THROW((void)shear_deck(s, 10e9, f), std::logic_error);
  }
}
