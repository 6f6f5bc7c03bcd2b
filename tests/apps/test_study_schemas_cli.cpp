// Every key a study's driver reads is in its schema: for each registered
// study (`wearscale studies`) and each table its keys are in, an unknown key
// in that table makes the driver list the keys it read there, and each of
// them must be in docs/keys.md, which the KeysDoc test keeps equal to what
// the schemas generate. A study is probed with the example of its command's
// --help, so a new study is checked as soon as it is registered with one.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"
#include "scratch_dir.hpp"

namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
const ScratchDir work_scratch("wearscale_study_schemas_");
const fs::path work = work_scratch.path();

struct Probe {
  std::string table, args;  // the table probed, and a command whose other keys are valid
};

// "keys read in [TABLE]: a, b, c (did you mean ...)" → {a, b, c}
std::vector<std::string> keys_read(const std::string& err, const std::string& table) {
  const std::string head = "keys read in [" + table + "]: ";
  const auto at = err.find(head);
  if (at == std::string::npos) return {};
  std::string list = err.substr(at + head.size());
  list = list.substr(0, std::min(list.find(" ("), list.find('\n')));
  std::vector<std::string> out;
  std::stringstream ss(list);
  for (std::string k; std::getline(ss, k, ',');) out.push_back(k.substr(k.find_first_not_of(' ')));
  return out;
}
}  // namespace

namespace {
// The command that runs `study`: "dem/rough_shear" → "dem rough-shear" (the pipeline: run).
std::string command_of(const std::string& study) {
  if (study == "pipeline") return "run";
  std::string c = study;
  std::replace(c.begin(), c.end(), '/', ' ');
  std::replace(c.begin(), c.end(), '_', '-');
  return c;
}

// The first example of `command`'s --help that runs it, without its comment
// and its --out, the case files of cases/ named from the source folder.
std::string example_of(const std::string& command) {
  const auto help = run_cli(command + " --help", work);
  std::stringstream ss(help.out);
  const std::string head = "  wearscale " + command + " ";
  for (std::string line; std::getline(ss, line);) {
    if (!line.starts_with(head)) continue;
    line = line.substr(std::string("  wearscale ").size());
    line = line.substr(0, line.find("    #"));
    if (const auto out = line.find(" --out "); out != std::string::npos) {
      const auto end = line.find(' ', out + 7);
      line.erase(out, end == std::string::npos ? std::string::npos : end - out);
    }
    for (std::size_t at = 0; (at = line.find("cases/", at)) != std::string::npos; at += 6) {
      line.insert(at, std::string(WEARSCALE_SOURCE_DIR) + "/");
      at += std::string(WEARSCALE_SOURCE_DIR).size() + 1;
    }
    return line;
  }
  return {};
}

// The tables of a study's keys ("dem.rough_shear.d0" → "dem.rough_shear"), but a
// [materials.define.<name>] (no case of the example defines one).
std::set<std::string> tables_of(const nlohmann::json& keys) {
  std::set<std::string> out;
  for (const auto& k : keys) {
    const std::string key = k["key"];
    if (key.find('<') != std::string::npos || key.find('.') == std::string::npos) continue;
    out.insert(key.substr(0, key.rfind('.')));
  }
  return out;
}
}  // namespace

TEST(StudySchemas, ListEveryKeyTheirDriversRead) {
  const std::string keys_md = slurp(fs::path(WEARSCALE_SOURCE_DIR) / "docs" / "keys.md");
  const auto list = run_cli("studies --json", work);
  ASSERT_EQ(list.status, 0) << list.err;
  std::size_t studies = 0;
  for (const auto& study : nlohmann::json::parse(list.out)) {
    const std::string name = study["name"];
    if (name == "pipeline") continue;  // its tables are the runner's and the backends' (the test below)
    ++studies;
    const std::string command = command_of(name);
    const std::string example = example_of(command);
    ASSERT_FALSE(example.empty()) << name << ": `wearscale " << command << " --help` shows no example";
    const auto keys = run_cli("studies " + name + " --json", work);
    ASSERT_EQ(keys.status, 0) << keys.err;
    std::size_t listed = 0;
    for (const auto& table : tables_of(nlohmann::json::parse(keys.out)["keys"])) {
      const auto r = run_cli(example + " --set " + table + ".zz_not_a_key=1 --out out", work);
      EXPECT_EQ(r.status, 2) << name << ", [" << table << "]: " << r.err;
      for (const auto& k : keys_read(r.err, table)) {
        EXPECT_THAT(keys_md, HasSubstr("`" + table + "." + k + "`")) << name << ": not in its schema";
        ++listed;
      }
    }
    EXPECT_GT(listed, 0u) << name << ": its example lists no key read in any of its tables";
  }
  EXPECT_GE(studies, 12u) << "the registered studies";
  EXPECT_FALSE(fs::exists(work / "out")) << "nothing may be written";
}

namespace {
// The keys docs/keys.md lists in [table] itself (not in a sub-table), by their leaf names.
std::set<std::string> keys_listed(const std::string& keys_md, const std::string& table) {
  std::set<std::string> out;
  const std::string head = "| `" + table + ".";
  std::stringstream ss(keys_md);
  for (std::string line; std::getline(ss, line);) {
    if (!line.starts_with(head)) continue;
    const std::string key = line.substr(head.size(), line.find('`', head.size()) - head.size());
    if (key.find('.') == std::string::npos) out.insert(key);
  }
  return out;
}
}  // namespace

// The studies whose keys are their key tables (wear maps, surfaces, the
// strength table's [output]): the keys a case's driver reads in its table
// are exactly those its schema lists, so that every declared key is read
// and only declared ones.
TEST(StudySchemas, TheKeyTableStudiesReadEveryKeyTheyDeclareAndNoOther) {
  const std::string keys_md = slurp(fs::path(WEARSCALE_SOURCE_DIR) / "docs" / "keys.md");
  const Probe probes[] = {
      {"wearmap.analytic2d", "wearmap analytic2d"},
      {"wearmap.analytic3d", "wearmap analytic3d"},
      {"wearmap.rough", "wearmap rough"},
      {"surface.generate", "surface generate --n 16 --size 1e-3 --hurst 0.8 --kl 1 --ks 4 --sa 1e-6"},
      {"surface.analyze", "surface analyze not_read_before_the_keys.h5"},
  };
  for (const auto& p : probes) {
    const auto r = run_cli(p.args + " --set " + p.table + ".zz_not_a_key=1 --out out", work);
    EXPECT_EQ(r.status, 2) << p.table << ": " << r.err;
    const auto read = keys_read(r.err, p.table);
    const std::set<std::string> read_set(read.begin(), read.end());
    const auto listed = keys_listed(keys_md, p.table);
    EXPECT_GE(listed.size(), 3u) << p.table << ": not in docs/keys.md";
    EXPECT_EQ(read_set, listed) << p.table << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(work / "out")) << "nothing may be written";
}

// The runner's own tables and the scale backends' tables of the pipeline: an
// unknown key in each lists the keys read there, each in docs/keys.md (which
// the key tables generate), and a key the page lists for it is read.
TEST(StudySchemas, TheRunnersAndTheBackendsKeysAreTheirTables) {
  const std::string keys_md = slurp(fs::path(WEARSCALE_SOURCE_DIR) / "docs" / "keys.md");
  const std::string cases = std::string(WEARSCALE_SOURCE_DIR) + "/cases/";
  const std::string pin_on_disc = "run '" + cases + "pin_on_disc_si_oxide.toml'";
  const Probe probes[] = {
      {"case", pin_on_disc},
      {"run", pin_on_disc},
      {"sweep", "run '" + cases + "oxide_thickness_sweep.toml'"},
      {"scale.macro", pin_on_disc},
      {"scale.macro", "run '" + cases + "hertz_pin.toml'"},
      {"scale.molecular", "run '" + cases + "scale_link.toml'"},
      {"scale.nano", "run '" + cases + "junction_sio2.toml'"},
      {"materials", pin_on_disc},
  };
  for (const auto& p : probes) {
    const auto r = run_cli(p.args + " --set " + p.table + ".zz_not_a_key=1 --out out", work);
    EXPECT_EQ(r.status, 2) << p.table << ": " << r.err;
    const auto keys = keys_read(r.err, p.table);
    EXPECT_FALSE(keys.empty()) << p.table << ": " << r.err;
    for (const auto& k : keys)
      // define, layer: tables whose keys are listed under them
      if (k != "define" && k != "layer")
        EXPECT_THAT(keys_md, HasSubstr("`" + p.table + "." + k + "`")) << "not in its table";
  }
  EXPECT_FALSE(fs::exists(work / "out")) << "nothing may be written";
}

namespace {
// The keys docs/keys.md lists for `study` in `table` ("dem/rough_shear", "dem.rough_shear"):
// the rows of the study's key tables, as the KeysDoc test keeps the page.
std::vector<std::string> keys_listed(const std::string& keys_md, const std::string& study, const std::string& table) {
  const std::string heading = "## `" + study + "`\n";
  const auto start = keys_md.find(heading);
  if (start == std::string::npos) return {};
  const auto end = keys_md.find("\n## ", start + heading.size());
  std::stringstream section(keys_md.substr(start, end - start));
  std::vector<std::string> out;
  const std::string head = "| `" + table + ".";
  for (std::string line; std::getline(section, line);) {
    if (!line.starts_with(head)) continue;
    const std::string key = line.substr(head.size(), line.find('`', head.size()) - head.size());
    if (key.find('.') == std::string::npos) out.push_back(key);
  }
  return out;
}
}  // namespace

// Each DEM study reads every key its key tables declare, and no other: the
// keys read in [dem] and in its own table are those docs/keys.md lists for it.
TEST(StudySchemas, TheDemStudiesReadEveryKeyTheirTablesDeclare) {
  const std::string keys_md = slurp(fs::path(WEARSCALE_SOURCE_DIR) / "docs" / "keys.md");
  struct DemProbe {
    std::string study, table, args;
  };
  // dem.friction is read for the hooke law only: the sliding cells' probes of [dem] take that law
  // (the studies of the cohesive law's strengths declare no friction).
  const DemProbe probes[] = {
      {"dem/patch_test", "dem.patch_test", "dem patch-test"},
      {"dem/junction", "dem", "dem junction --material SiO2 --D 20e-9 --d0 6e-9"},
      {"dem/junction", "dem.junction", "dem junction --material SiO2 --D 20e-9 --d0 6e-9"},
      {"dem/rough_shear", "dem", "dem rough-shear --material SiO2 --d0 3e-9 --set 'dem.law=\"hooke\"'"},
      {"dem/rough_shear", "dem.rough_shear", "dem rough-shear --material SiO2 --d0 3e-9"},
      {"dem/trapped_particles", "dem",
       "dem trapped-particles --material SiO2 --n 2 --D 20e-9 --d0 6e-9 --set 'dem.law=\"hooke\"'"},
      {"dem/trapped_particles", "dem.trapped_particles", "dem trapped-particles --material SiO2 --n 2 --D 20e-9 --d0 6e-9"},
      {"dem/oxide_asperity", "dem.oxide_asperity", "dem oxide-asperity --d0 6e-9"},
  };
  for (const auto& p : probes) {
    const auto r = run_cli(p.args + " --set " + p.table + ".zz_not_a_key=1 --out out", work);
    EXPECT_EQ(r.status, 2) << p.table << ": " << r.err;
    auto read = keys_read(r.err, p.table);
    auto listed = keys_listed(keys_md, p.study, p.table);
    std::sort(read.begin(), read.end());
    std::sort(listed.begin(), listed.end());
    EXPECT_FALSE(listed.empty()) << p.study << " lists no key of [" << p.table << "]";
    EXPECT_EQ(read, listed) << p.study << ": the keys read in [" << p.table << "] are not those its tables declare";
  }
  EXPECT_FALSE(fs::exists(work / "out")) << "nothing may be written";
}

// The contact study reads every key of [contact] and [contact.rough] its key
// table declares, and no other: the keys read over its modes (frictionless
// with young and ν, Coulomb, Tresca, a height file) are those docs/keys.md lists.
TEST(StudySchemas, TheContactStudyReadsEveryKeyItsTableDeclares) {
  const std::string keys_md = slurp(fs::path(WEARSCALE_SOURCE_DIR) / "docs" / "keys.md");
  fs::create_directories(work);
  std::ofstream(work / "h.txt") << "# lx = 1 mm\n1e-6 2e-6\n3e-6 4e-6\n";
  const std::string sphere = "contact --set contact.grid=16 --set contact.size=1e-3 --set contact.sphere.radius=1e-2 "
                             "--set contact.young=1e9 --poisson 0.3 --pressure 1e6 ";
  const std::string rough =
      "contact '" WEARSCALE_SOURCE_DIR "/cases/rough_contact.toml' --set contact.grid=64 --set contact.rough.k_s=16 ";
  const std::map<std::string, std::vector<std::string>> probes = {
      {"contact",
       {sphere, sphere + "--friction coulomb --mu 0.3 ", sphere + "--friction tresca --shear-strength 1e6 ",
        "contact --surface h.txt --e-star 1e9 --pressure 1e6 "}},
      {"contact.rough", {rough}},
  };
  for (const auto& [table, commands] : probes) {
    std::set<std::string> read;
    for (const auto& command : commands) {
      const auto r = run_cli(command + "--set " + table + ".zz_not_a_key=1 --out out", work);
      EXPECT_EQ(r.status, 2) << command << ": " << r.err;
      const auto keys = keys_read(r.err, table);
      EXPECT_FALSE(keys.empty()) << command << ": " << r.err;
      read.insert(keys.begin(), keys.end());
    }
    const auto listed_keys = keys_listed(keys_md, "contact", table);
    const std::set<std::string> listed(listed_keys.begin(), listed_keys.end());
    EXPECT_GE(listed.size(), 5u) << table << ": not in docs/keys.md";
    EXPECT_EQ(read, listed) << "[" << table << "]: the keys read are not those its table declares";
  }
  EXPECT_FALSE(fs::exists(work / "out")) << "nothing may be written";
}
