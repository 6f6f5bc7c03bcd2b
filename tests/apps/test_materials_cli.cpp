// A material of the user's own through the scale link, as a user runs it:
// `wearscale run` on a case that defines nickel with its interatomic model
// and asks molecular/lammps for its strengths. A fake lmp (a script) stands
// for LAMMPS: it answers the elastic-constant decks with an isotropic solid
// and every shear deck with a curve peaking at 12 GPa and sliding at 2 GPa,
// so the junction model's figures are known in closed form: p_crit = 12 GPa
// (7.5), μ0 = 2/12 (9.13), d* = 12πγG/((2 − ν) p_crit²) (4.35). The real
// LAMMPS runs are in tests/md/lammps/.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_materials_cli_");
const fs::path work = work_scratch.path();

// The fake lmp: elastic decks (they write elastic.txt) get an isotropic solid of
// C11 = 137, C12 = 38.6, C44 = 49.2 GPa; shear decks a curve and their sample.txt.
fs::path fake_lmp() {
  const fs::path file = work / "lmp";
  if (fs::exists(file)) return file;
  fs::create_directories(work);
  std::ofstream rows(work / "elastic-rows.txt");
  const double c11 = 137.0, c12 = 38.6, c44 = 49.2;
  const double c[6][6] = {{c11, c12, c12, 0, 0, 0}, {c12, c11, c12, 0, 0, 0}, {c12, c12, c11, 0, 0, 0},
                          {0, 0, 0, c44, 0, 0},     {0, 0, 0, 0, c44, 0},     {0, 0, 0, 0, 0, c44}};
  rows << "0 0 0 0 0 0 0 0 0 10.56 10.56 10.56\n";
  int k = 1;
  for (int j = 0; j < 6; ++j)
    for (int sign : {1, -1}) {
      rows << k++ << " " << j + 1 << " " << sign;
      for (int i = 0; i < 6; ++i) rows << " " << -sign * 1e-3 * c[i][j] * 1e4;
      rows << " 10.56 10.56 10.56\n";
    }
  std::ofstream curve(work / "shear-rows.txt");
  curve << "# TimeStep v_strain v_tau v_p_n v_h c_t_mobile\n";
  for (int i = 1; i <= 60; ++i)
    curve << 2000 + 100 * i << " " << i / 100.0 << " " << (i <= 30 ? i * 0.4 : 2.0) << " 0 19 300\n";
  std::ofstream(file) << "#!/bin/sh\n"
                         "if [ \"$1\" = \"-h\" ]; then echo 'Large-scale Atomic/Molecular Massively Parallel "
                         "Simulator - 1 Jan 2000 - fake'; exit 0; fi\n"
                         "if grep -q elastic.txt in.lammps; then cp '" << (work / "elastic-rows.txt").string()
                      << "' elastic.txt; printf 'atoms 108\\ncompleted yes\\n' > sample.txt; exit 0; fi\n"
                         "cp '" << (work / "shear-rows.txt").string() << "' shear.dat\n"
                         "printf 'atoms 936\\nlx_A 21.12\\nly_A 21.12\\nh0_A 19.0\\nh_gap_A 15.0\\ncompleted yes\\n' > "
                         "sample.txt\n";
  fs::permissions(file, fs::perms::owner_all);
  return file;
}

std::string nickel_case(const std::string& elements) {
  return "[case]\nname = \"ni\"\n[materials]\npin = \"Ni\"\ndisc = \"Ni\"\n"
         "[materials.define.Ni]\nyoung = \"200 GPa\"\npoisson = 0.31\ndensity = \"8.9 g/cm^3\"\n"
         "surface_energy = \"2 J/m^2\"\ntensile_strength = \"20 GPa\"\nshear_strength = \"5 GPa\"\n"
         "[materials.define.Ni.interatomic]\npair_style = \"eam\"\npotential = \"Ni_u3.eam\"\nelements = " +
         elements +
         "\nmasses = [58.6934]\nstructure = \"fcc\"\nlattice_constant = \"3.52 Å\"\n"
         "[scale.molecular]\nbackend = \"lammps\"\npressures = [\"0 GPa\", \"10 GPa\", \"20 GPa\"]\nlmp = \"" +
         fake_lmp().string() + "\"\n[scale.nano]\nbackend = \"analytic\"\n";
}
}  // namespace

TEST(MaterialsCli, ACaseDefinedMaterialGoesThroughTheScaleLinkLikeSilicon) {
  // The potential file must exist to be hashed: the installed one, else a stand-in beside the case.
  if (!fs::exists("/usr/share/lammps/potentials/Ni_u3.eam")) std::ofstream(work_scratch.file("Ni_u3.eam")) << "stand-in\n";
  const std::string text = nickel_case("[\"Ni\"]");  // (makes the folder and the fake lmp first)
  std::ofstream(work_scratch.file("ni.toml")) << text;
  const auto r = run_cli("run ni.toml --json --out out", work, "WEARSCALE_CACHE='" + (work / "cache").string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  const auto results = nlohmann::json::parse(r.out)["results"];
  EXPECT_NEAR(results["p_crit_Ni-Ni"]["value"].get<double>(), 12e9, 1e-3 * 12e9) << "σ_max = 12 GPa = p (7.5)";
  EXPECT_NEAR(results["mu0_Ni-Ni"]["value"].get<double>(), 2.0 / 12.0, 1e-6) << "σ_dyn(p_crit)/p_crit (9.13)";
  const double g = 200e9 / (2 * 1.31);
  EXPECT_NEAR(results["d_star_Ni-Ni"]["value"].get<double>(), 12 * M_PI * 2.0 * g / ((2 - 0.31) * 144e18), 1e-12)
      << "(4.35) with σ_j = p_crit";
  // The table in the project's CSV convention, with its provenance beside it.
  const std::string table = slurp(work / "out" / "strength_Ni.csv");
  EXPECT_EQ(table.substr(0, table.find('\n')), "pressure_Pa,sigma_max_Pa,sigma_dyn_Pa");
  EXPECT_EQ(table.substr(table.find('\n') + 1, table.find('\n', table.find('\n') + 1) - table.find('\n') - 1),
            "0.0,1.2e+10,2000000000.0");
  const auto sidecar = nlohmann::json::parse(slurp(work / "out" / "strength_Ni.csv.json"));
  std::string notes;
  for (const auto& n : sidecar["notes"]) notes += n.get<std::string>() + "\n";
  EXPECT_THAT(notes, HasSubstr("material: Ni"));
  EXPECT_THAT(notes, HasSubstr("potential_sha256: "));
  EXPECT_THAT(notes, HasSubstr("lammps_version: 1 Jan 2000 - fake"));
  EXPECT_THAT(notes, HasSubstr("elastic_check: passed"));
}

TEST(MaterialsCli, AnElementNameThatWouldChangeTheDeckIsRefusedAtItsKeyAndNothingRuns) {
  const std::string text = nickel_case("[\"Ni\\nshell touch pwned\"]");
  std::ofstream(work_scratch.file("bad.toml")) << text;
  const auto r = run_cli("run bad.toml --out bad", work, "WEARSCALE_CACHE='" + (work / "cache-bad").string() + "'");
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr("materials.define.Ni.interatomic.elements"));
  EXPECT_FALSE(fs::exists(work / "bad"));
  EXPECT_FALSE(fs::exists(work / "cache-bad" / "lammps")) << "no LAMMPS run started";
  EXPECT_FALSE(fs::exists(work / "pwned"));
}
