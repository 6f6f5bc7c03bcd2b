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

bool declared(const Schema& schema, const std::string& key) {
  for (const auto& row : schema)
    if (row.key == key || (row.type == "table" && key.starts_with(row.key + "."))) return true;
  return false;
}

// Makes every scale of `cfg` that declares its keys (its factory reads them all).
std::vector<std::pair<std::string, std::string>> make_declared_scales(const Config& cfg) {
  std::vector<std::pair<std::string, std::string>> made;
  for (const auto& kind : cfg.keys("scale")) {
    const Config section = cfg.section("scale." + kind);
    const std::string backend = section.string("backend");
    if (!has_backend_keys(kind, backend)) continue;
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
  for (const char* b : {"macro/bem-pin-on-disc", "macro/hertz", "molecular/table"})
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
    if (!has_backend_keys(info.kind, info.name)) continue;
    std::set<std::string> names;
    for (const auto& row : backend_schema(info.kind, info.name)) {
      EXPECT_TRUE(names.insert(row.key).second) << info.id() << ": " << row.key << " twice";
      EXPECT_FALSE(row.type.empty()) << row.key;
      EXPECT_FALSE(row.doc.empty()) << row.key;
      EXPECT_TRUE(row.key.starts_with("scale." + info.kind + ".")) << row.key;
    }
  }
}
