// Each scale backend's keys are declared once, in its key table: reading the
// shipped cases touches only declared keys, reads every key a case gives and
// every declared one, and a key no backend declares is refused with the
// closest declared one.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "input_error_of.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "wearscale/coupling/backend_keys.hpp"
#include "wearscale/coupling/scale.hpp"
#include "wearscale/io/config.hpp"

using namespace wearscale;
using namespace wearscale::coupling;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

// The shipped cases of the pipeline study (those with [scale.*] tables).
std::vector<fs::path> pipeline_cases() {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(WEARSCALE_CASES_DIR))
    if (e.path().extension() == ".toml" && Config::load(e.path()).has("scale")) out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

// `key` as read, an element of an array ("pressures[1]") as its array.
bool declared(const Schema& schema, std::string key) {
  if (const auto bracket = key.find('['); bracket != std::string::npos) key.resize(bracket);
  for (const auto& row : schema)
    if (row.key == key || (row.type == "table" && key.starts_with(row.key + "."))) return true;
  return false;
}

// Makes every scale of `cfg` (its factory reads all its keys).
std::vector<std::pair<std::string, std::string>> make_declared_scales(const Config& cfg) {
  std::vector<std::pair<std::string, std::string>> made;
  for (const auto& kind : cfg.keys("scale")) {
    const Config section = cfg.section("scale." + kind);
    const std::string backend = section.string("backend");
    (void)scale_registry().create(kind, backend, ScaleSetup{kind, backend, section, cfg});
    made.emplace_back(kind, backend);
  }
  return made;
}

}  // namespace

TEST(BackendKeys, TheShippedCasesReadOnlyDeclaredKeysAndEveryDeclaredOne) {
  const auto cases = pipeline_cases();
  ASSERT_GE(cases.size(), 8u);
  std::set<std::string> backends_seen;
  for (const auto& file : cases) {
    const Config cfg = Config::load(file);
    const auto made = make_declared_scales(cfg);
    const auto read = cfg.keys_read();
    for (const auto& [kind, backend] : made) {
      backends_seen.insert(kind + "/" + backend);
      const Schema schema = backend_schema(kind, backend);
      const std::string prefix = "scale." + kind + ".";
      for (const auto& key : read) {
        if (key.starts_with(prefix)) EXPECT_TRUE(declared(schema, key)) << file << ": reads undeclared " << key;
      }
      for (const auto& row : schema) {
        if (row.type != "table")
          EXPECT_TRUE(std::find(read.begin(), read.end(), row.key) != read.end())
              << file << ": declares " << row.key << " but reads it not";
      }
      // Every key the case gives in the table is read by its backend.
      EXPECT_NO_THROW(cfg.section("scale." + kind).reject_unknown_keys()) << file;
    }
    // [materials]: pin, disc and layer as declared once (the backends without a table read them too).
    const Schema materials = materials_schema();
    for (const auto& key : read) {
      if (key.starts_with("materials.") && !key.starts_with("materials.define."))
        EXPECT_TRUE(declared(materials, key)) << file << ": reads undeclared " << key;
    }
  }
  for (const char* b : {"macro/bem-pin-on-disc", "macro/hertz", "molecular/table", "nano/dem"})
    EXPECT_EQ(backends_seen.count(b), 1u) << b << " is read by no shipped case";
}

TEST(BackendKeys, AnUndeclaredKeyIsRefusedWithTheClosestDeclaredOne) {
  Config cfg = Config::load(fs::path(WEARSCALE_CASES_DIR) / "pin_on_disc_si_oxide.toml");
  cfg.override_value("scale.macro.time_stpe=0.01");
  make_declared_scales(cfg);
  const std::string e = input_error_of([&] { cfg.section("scale.macro").reject_unknown_keys(); });
  EXPECT_THAT(e, HasSubstr("scale.macro.time_stpe"));
  EXPECT_THAT(e, HasSubstr("did you mean 'time_step'?"));
}

TEST(BackendKeys, TheTimeStepStaysBoundedByTheDistanceOverTheVelocity) {
  // distance 0.05 m at 8 mm/s: 6.25 s
  Config cfg = Config::load(fs::path(WEARSCALE_CASES_DIR) / "pin_on_disc_si_oxide.toml");
  cfg.override_value("scale.macro.distance=0.05");
  cfg.override_value("scale.macro.velocity=\"8 mm/s\"");
  cfg.override_value("scale.macro.time_step=6.3");
  const std::string e = input_error_of([&] { make_declared_scales(cfg); });
  EXPECT_THAT(e, HasSubstr("scale.macro.time_step"));
  EXPECT_THAT(e, HasSubstr("(0, 6.25] s"));
  const Schema schema = backend_schema("macro", "bem-pin-on-disc");
  const auto row = std::find_if(schema.begin(), schema.end(), [](const auto& k) { return k.key == "scale.macro.time_step"; });
  ASSERT_NE(row, schema.end());
  EXPECT_EQ(row->range, "(0, distance/velocity]");
  EXPECT_EQ(row->fallback, "0.02");
  EXPECT_EQ(row->unit, "s");
}

TEST(BackendKeys, EachSchemaNamesItsKeysOnceWithATypeAndAMeaning) {
  for (const auto& info : scale_registry().list()) {
    EXPECT_TRUE(static_cast<bool>(info.keys)) << info.id() << ": a registry entry without its keys";
    std::set<std::string> names;
    for (const auto& row : backend_schema(info.kind, info.name)) {
      EXPECT_TRUE(names.insert(row.key).second) << info.id() << ": " << row.key << " twice";
      EXPECT_FALSE(row.type.empty()) << row.key;
      EXPECT_FALSE(row.doc.empty()) << row.key;
      EXPECT_TRUE(row.key.starts_with("scale." + info.kind + ".")) << row.key;
    }
  }
}

namespace {
// The error of making scale `kind` of `cfg` (its key table reading every key).
std::string scale_error(const Config& cfg, const std::string& kind) {
  const Config section = cfg.section("scale." + kind);
  const std::string backend = section.string("backend");
  return input_error_of(
      [&] { (void)scale_registry().create(kind, backend, ScaleSetup{kind, backend, section, cfg}); });
}
}  // namespace

TEST(BackendKeys, TheDemNanoscaleRefusesAJunctionNarrowerThanOneParticleOfItsCell) {
  // L = 25 d0: the narrowest junction is one particle, D/L = 1/25 = 0.04.
  Config cfg = Config::load(fs::path(WEARSCALE_CASES_DIR) / "junction_sio2.toml");
  cfg.override_value("scale.nano.contact_ratios=[0.03, 1.0]");
  const std::string e = scale_error(cfg, "nano");
  EXPECT_THAT(e, HasSubstr("--set"));  // where the value came from
  EXPECT_THAT(e, HasSubstr("scale.nano.contact_ratios"));
  EXPECT_THAT(e, HasSubstr("D/L = 0.03 is less than one particle of the 25-particle cell"));
  EXPECT_THAT(e, HasSubstr("[0.04, 1]"));
  cfg.override_value("scale.nano.contact_ratios=[0.04, 1.0]");
  EXPECT_NO_THROW(make_declared_scales(cfg));
}

TEST(BackendKeys, TheDemNanoscaleRefusesAnEmptyListAndAnUnknownAmorphousMaterial) {
  Config empty = Config::load(fs::path(WEARSCALE_CASES_DIR) / "junction_sio2.toml");
  empty.override_value("scale.nano.pressures=[]");
  const std::string e = scale_error(empty, "nano");
  EXPECT_THAT(e, HasSubstr("scale.nano.pressures"));
  EXPECT_THAT(e, HasSubstr("an empty list"));
  EXPECT_THAT(e, HasSubstr("≥ 0 Pa"));
  Config unknown = Config::load(fs::path(WEARSCALE_CASES_DIR) / "junction_sio2.toml");
  unknown.override_value("scale.nano.amorphous=\"Cu\"");
  const std::string u = scale_error(unknown, "nano");
  EXPECT_THAT(u, HasSubstr("scale.nano.amorphous"));
  EXPECT_THAT(u, HasSubstr("no material 'Cu'"));
  Config none = Config::load(fs::path(WEARSCALE_CASES_DIR) / "junction_sio2.toml");
  none.override_value("scale.nano.amorphous=\"none\"");
  EXPECT_NO_THROW(make_declared_scales(none));
}

// A SiO2 pin on SiO2 with the LAMMPS shear test and its melt-quench: the
// backend reads only declared keys (those of the shear test's key table) and
// every declared one; a bad value names its key and what is allowed.
TEST(BackendKeys, TheLammpsMolecularScaleReadsTheShearTestsKeyTable) {
  const std::string text = R"(
[materials]
pin = "SiO2"
disc = "SiO2"
[scale.molecular]
backend = "lammps"
outside = "clamp"
pressures = ["0 GPa", "10 GPa"]
strain_end = 0.6
[scale.molecular.quench]
hold_time = "45 ps"
)";
  const Config cfg = Config::from_string(text, "lammps.toml");
  ASSERT_EQ(make_declared_scales(cfg).size(), 1u);
  const Schema schema = backend_schema("molecular", "lammps");
  const auto read = cfg.keys_read();
  for (const auto& key : read) {
    if (key.starts_with("scale.molecular.")) {
      EXPECT_TRUE(declared(schema, key)) << "reads undeclared " << key;
    }
  }
  for (const auto& row : schema) {
    if (row.type != "table") {
      EXPECT_TRUE(std::find(read.begin(), read.end(), row.key) != read.end()) << "declares " << row.key
                                                                              << " but reads it not";
    }
  }
  EXPECT_NO_THROW(cfg.section("scale.molecular").reject_unknown_keys());

  Config bad = Config::from_string(text, "lammps.toml");
  bad.override_value("scale.molecular.strain_end=20");
  const std::string e = scale_error(bad, "molecular");
  EXPECT_THAT(e, HasSubstr("scale.molecular.strain_end"));
  EXPECT_THAT(e, HasSubstr("(0, 10]"));
}
