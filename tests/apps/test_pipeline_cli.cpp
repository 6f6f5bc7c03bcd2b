// The multiscale pipeline through `wearscale run`: every exchanged quantity
// names its producer in run.h5, swapping a backend changes the provenance
// and nothing else of the layout, and a broken case is refused with status 2.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_pipeline_cli_");
const std::filesystem::path work = work_scratch.path();
const std::string scale_link = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/scale_link.toml'";
const std::string pin_on_disc = "'" + std::string(WEARSCALE_SOURCE_DIR) + "/cases/pin_on_disc_si_oxide.toml'";
const std::string short_run = " --set scale.macro.distance=0.01 --set scale.macro.grid=64";
}  // namespace

TEST(PipelineCli, EveryExchangedQuantityNamesItsProducer) {
  ASSERT_EQ(run_cli("run " + pin_on_disc + short_run + " --out pod", work).status, 0);
  wearscale::H5Reader h5(work / "pod" / "run.h5");
  EXPECT_EQ(h5.string_attribute("/exchange/ShearStrength/SiO2", "producer"), "molecular/table");
  EXPECT_EQ(h5.string_attribute("/exchange/ShearStrength/Si", "producer"), "molecular/table");
  EXPECT_EQ(h5.string_attribute("/exchange/InterfaceLaw/SiO2-Si", "producer"), "nano/analytic");
  EXPECT_EQ(h5.string_attribute("/exchange/InterfaceLaw/SiO2-SiO2", "producer"), "nano/analytic");
  EXPECT_EQ(h5.string_attribute("/exchange/MacroResult/pin-disc", "producer"), "macro/bem-pin-on-disc");
  EXPECT_THAT(h5.string_attribute("/", "case_toml"), HasSubstr("bem-pin-on-disc"));
  EXPECT_TRUE(h5.exists("/macro/series/friction"));
  EXPECT_TRUE(h5.exists("/macro/final/pin"));
}

TEST(PipelineCli, SwappingTheMolecularBackendChangesOnlyTheProvenance) {
  ASSERT_EQ(run_cli("run " + scale_link + " --out table", work).status, 0);
  fs::create_directories(work);
  const auto ideal_case = work / "ideal.toml";
  {
    std::ifstream in(std::string(WEARSCALE_SOURCE_DIR) + "/cases/scale_link.toml");
    std::ofstream out(ideal_case);
    std::string line;
    while (std::getline(in, line))
      if (line.rfind("data =", 0) != 0) out << line << '\n';  // "data" belongs to the table backend
  }
  ASSERT_EQ(run_cli("run '" + ideal_case.string() + "' --set scale.molecular.backend=ideal --out ideal", work).status, 0);
  wearscale::H5Reader a(work / "table" / "run.h5"), b(work / "ideal" / "run.h5");
  EXPECT_EQ(a.string_attribute("/exchange/ShearStrength/Si", "producer"), "molecular/table");
  EXPECT_EQ(b.string_attribute("/exchange/ShearStrength/Si", "producer"), "molecular/ideal");
  for (const char* path : {"/exchange/InterfaceLaw/SiO2-Si", "/results/mu0_SiO2-Si", "/results/p_crit_SiO2-SiO2"}) {
    EXPECT_TRUE(a.exists(path)) << path;
    EXPECT_TRUE(b.exists(path)) << path;
  }
  EXPECT_NE(a.read_scalar("/results/mu0_SiO2-Si"), b.read_scalar("/results/mu0_SiO2-Si"));
}

TEST(PipelineCli, RunJsonGivesTheHeadlineFigures) {
  const auto r = run_cli("run " + pin_on_disc + short_run + " --out pod-json --json", work);
  ASSERT_EQ(r.status, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* k : {"mu_mean", "mu_final", "pin_wear", "disc_wear", "contact_solves"})
    EXPECT_TRUE(j["results"].contains(k)) << k;
  EXPECT_NEAR(j["results"]["mu_mean"]["value"].get<double>(), 0.837, 0.005);  // still on the oxide at 1 cm
}

struct BadCase {
  std::string name, args, expected;
};
void PrintTo(const BadCase& b, std::ostream* os) { *os << b.name; }
class PipelineCliBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(PipelineCliBadInput, ExitsWithStatus2SayingWhatToChange) {
  const auto& p = GetParam();
  const auto out = work / ("bad-" + p.name);
  const auto r = run_cli("run " + pin_on_disc + short_run + " --out '" + out.string() + "' " + p.args, work);
  EXPECT_EQ(r.status, 2) << r.err;
  EXPECT_THAT(r.err, HasSubstr(p.expected));
  EXPECT_FALSE(fs::exists(out));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PipelineCliBadInput,
    ::testing::Values(
        BadCase{"negative_thickness", "--set materials.layer.thickness=-1e-6", "materials.layer.thickness"},
        BadCase{"unknown_backend", "--set scale.nano.backend=quantum", "unknown backend; allowed: analytic"},
        BadCase{"missing_table", "--set scale.molecular.tables.Si=/nonexistent/si.csv", "scale.molecular.tables.Si"},
        BadCase{"no_provider", "--set scale.nano.backend=analytic --set scale.molecular.backend=table "
                               "--set materials.define.Cu.young=1e11 --set materials.define.Cu.poisson=0.3 "
                               "--set materials.define.Cu.density=8900 --set materials.define.Cu.surface_energy=1.7 "
                               "--set materials.define.Cu.tensile_strength=1e9 --set materials.define.Cu.shear_strength=5e8 "
                               "--set materials.disc=Cu",
                "no shipped 'thesis' strength table for material 'Cu'"},
        BadCase{"unknown_material", "--set materials.disc=Unobtainium", "materials.disc"},
        BadCase{"bad_sweep_key", "--set sweep.key=scale.macro.nothing --set 'sweep.values=[1]'", "sweep.key"}),
    [](const auto& p) { return p.param.name; });

TEST(PipelineCli, AScaleWhoseInputNobodyProvidesIsRefused) {
  // Without a molecular scale, the junction model has no strengths to work on.
  fs::create_directories(work);
  const auto no_molecular = work / "no_molecular.toml";
  {
    std::ofstream out(no_molecular);
    out << "[case]\nname = \"x\"\n[materials]\npin = \"SiO2\"\ndisc = \"Si\"\n[scale.nano]\nbackend = \"analytic\"\n";
  }
  const auto r = run_cli("run '" + no_molecular.string() + "' --out nm", work);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, HasSubstr("nano/analytic needs ShearStrength(SiO2), but no scale of this case provides it"));
}

// nano/dem and nano/analytic are interchangeable: the same case runs with
// either, the exchanged keys and headline names are the same, the producer
// and provenance differ. The DEM runs (one D = L junction per interface on a
// reduced cell) are cached by their inputs: the second run computes none.
TEST(PipelineCli, SwappingTheNanoBackendChangesOnlyTheProvenance) {
  const std::string dem = " --set scale.nano.backend=dem --set scale.nano.length=12 --set scale.nano.height=6"
                          " --set scale.nano.velocity=50 --set 'scale.nano.contact_ratios=[1.0]'"
                          " --set 'scale.nano.pressures=[1e9]' --set scale.nano.cache_dir='" +
                          (work / "dem-cache").string() + "'";
  fs::remove_all(work / "dem-cache");
  const auto analytic = run_cli("run " + scale_link + " --json --out analytic", work);
  ASSERT_EQ(analytic.status, 0) << analytic.err;
  const auto cold = run_cli("run " + scale_link + dem + " --json --out dem", work);
  ASSERT_EQ(cold.status, 0) << cold.err;
  const auto warm = run_cli("run " + scale_link + dem + " --json --out dem-warm", work);
  ASSERT_EQ(warm.status, 0) << warm.err;
  EXPECT_THAT(cold.err, HasSubstr("nano/dem: SiO2/Si junction D/L = 1"));
  EXPECT_THAT(warm.err, ::testing::Not(HasSubstr("junction D/L")));  // read from the cache

  const auto a = nlohmann::json::parse(analytic.out), d = nlohmann::json::parse(cold.out),
             w = nlohmann::json::parse(warm.out);
  for (const auto& [name, v] : a["results"].items()) EXPECT_TRUE(d["results"].contains(name)) << name;
  EXPECT_EQ(d["results"]["mu0_SiO2-Si"]["value"], w["results"]["mu0_SiO2-Si"]["value"]);
  wearscale::H5Reader ha(work / "analytic" / "run.h5"), hd(work / "dem" / "run.h5"), hw(work / "dem-warm" / "run.h5");
  for (const char* pair : {"/exchange/InterfaceLaw/SiO2-Si", "/exchange/InterfaceLaw/SiO2-SiO2"}) {
    EXPECT_EQ(ha.string_attribute(pair, "producer"), "nano/analytic");
    EXPECT_EQ(hd.string_attribute(pair, "producer"), "nano/dem");
    const auto p = nlohmann::json::parse(hd.string_attribute(pair, "provenance"));
    EXPECT_TRUE(p["parameters"].contains("fit")) << pair;
    ASSERT_EQ(p["parameters"]["runs"].size(), 1u) << pair;
    EXPECT_FALSE(p["parameters"]["runs"][0]["cached"].get<bool>());
    const auto pw = nlohmann::json::parse(hw.string_attribute(pair, "provenance"));
    EXPECT_TRUE(pw["parameters"]["runs"][0]["cached"].get<bool>());
  }
  EXPECT_EQ(ha.string_attribute("/exchange/ShearStrength/Si", "producer"),
            hd.string_attribute("/exchange/ShearStrength/Si", "producer"));
  EXPECT_TRUE(hd.exists("/nano/SiO2-Si/runs"));
  EXPECT_TRUE(fs::exists(work / "dem" / "junction_SiO2-Si.csv"));
}
