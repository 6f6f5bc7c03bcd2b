// Key tables: each key declared once against the member it fills; the reader
// does the typed getters (the same errors as Config's own), the schema lists
// the same keys with their defaults taken from the members' initializers.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "input_error_of.hpp"

#include <nlohmann/json.hpp>

#include "wearscale/io/key_table.hpp"

using namespace wearscale;
using ::testing::HasSubstr;

namespace {

enum class Track { Averaged, Resolved };

struct Inner {
  double tolerance = 1e-10;
};

struct Cell {
  long grid = 128;
  double size = 2e-3;
  double velocity = 8e-3;
  double distance = 0.5;
  double time_step = 0.02;
  bool periodic = true;
  Track track = Track::Averaged;
  std::string integrator = "explicit";
  Inner inner;
  double e_star = 0.0;
};

const KeyTable<Cell>& cell_keys() {
  static const auto table =
      KeyTable<Cell>()
          .integer("grid", &Cell::grid, Range::closed(8, 4096), "cells per side")
          .number("size", &Cell::size, Range::positive(), units::length, "side of the cell")
          .number("velocity", &Cell::velocity, Range::positive(), units::velocity, "sliding velocity")
          .number("distance", &Cell::distance, Range::positive(), units::length, "sliding distance")
          .number("time_step", &Cell::time_step, Range::positive(), units::time, "time step")
          .range_from([](const Cell& c) { return Range::open_closed(0.0, c.distance / c.velocity); },
                      "(0, distance/velocity]")
          .boolean("periodic", &Cell::periodic, "periodic images")
          .choice("track", &Cell::track,
                  std::vector<std::pair<std::string, Track>>{{"averaged", Track::Averaged},
                                                             {"resolved", Track::Resolved}},
                  "disc track")
          .choice("integrator", &Cell::integrator, {"explicit", "adaptive"}, "time integrator")
          .computed_text([](const Cell& c) { return c.track == Track::Averaged ? "adaptive" : "explicit"; },
                           "adaptive on an averaged track, else explicit")
          .number("tolerance", [](Cell& c) -> double& { return c.inner.tolerance; }, Range::open(0.0, 1e-3),
                  "solver tolerance")
          .number("e_star", &Cell::e_star, Range::positive(), units::pressure, "contact modulus")
          .computed_default([](const Cell& c) { return 1e9 * c.size / 2e-3; }, "1 GPa per 2 mm of size");
  return table;
}

}  // namespace

TEST(KeyTable, DefaultsComeFromTheMembersInitializersAndAreRecorded) {
  const auto c = Config::from_string("[cell]\ntrack = \"resolved\"\n", "cell.toml");
  Cell cell;
  cell_keys().read(c.section("cell"), cell);
  EXPECT_EQ(cell.grid, 128);
  EXPECT_EQ(cell.size, 2e-3);
  EXPECT_EQ(cell.time_step, 0.02);
  EXPECT_TRUE(cell.periodic);
  EXPECT_EQ(cell.track, Track::Resolved);
  EXPECT_EQ(cell.integrator, "explicit");  // computed: a resolved track
  EXPECT_EQ(cell.inner.tolerance, 1e-10);
  EXPECT_EQ(cell.e_star, 1e9);
  const auto& applied = c.applied_defaults();
  EXPECT_EQ(applied.at("cell.grid"), 128);
  EXPECT_EQ(applied.at("cell.integrator"), "explicit");
  EXPECT_EQ(applied.at("cell.e_star"), 1e9);
  EXPECT_FALSE(applied.contains("cell.track"));
  EXPECT_NO_THROW(c.reject_unknown_keys());
}

TEST(KeyTable, ValuesAreReadInSIWithUnitsAndMappedChoices) {
  const auto c = Config::from_string(
      "[cell]\ngrid = 64\nsize = \"4 mm\"\nvelocity = \"1 mm/s\"\ntime_step = \"2 s\"\nperiodic = false\n"
      "tolerance = 1e-8\n",
      "cell.toml");
  Cell cell;
  cell_keys().read(c.section("cell"), cell);
  EXPECT_EQ(cell.grid, 64);
  EXPECT_DOUBLE_EQ(cell.size, 4e-3);
  EXPECT_DOUBLE_EQ(cell.velocity, 1e-3);
  EXPECT_EQ(cell.time_step, 2.0);
  EXPECT_FALSE(cell.periodic);
  EXPECT_EQ(cell.integrator, "adaptive");  // computed: an averaged track
  EXPECT_EQ(cell.inner.tolerance, 1e-8);
  EXPECT_DOUBLE_EQ(cell.e_star, 2e9);
}

TEST(KeyTable, AnOutOfRangeValueGivesConfigsOwnError) {
  const auto c = Config::from_string("[cell]\ngrid = 4\n", "cell.toml");
  Cell cell;
  const std::string from_table = input_error_of([&] { cell_keys().read(c.section("cell"), cell); });
  const std::string from_getter = input_error_of([&] { (void)c.integer("cell.grid", Range::closed(8, 4096)); });
  EXPECT_EQ(from_table, from_getter);
  EXPECT_THAT(from_table, HasSubstr("cell.toml:2"));
  EXPECT_THAT(from_table, HasSubstr("cell.grid"));
  EXPECT_THAT(from_table, HasSubstr("4"));
  EXPECT_THAT(from_table, HasSubstr("[8, 4096]"));
}

TEST(KeyTable, ADependentRangeIsEnforcedWithTheValuesOfTheKeysReadBefore) {
  // distance/velocity = 0.5 m / 8 mm/s = 62.5 s
  const auto c = Config::from_string("[cell]\ntime_step = 63\n", "cell.toml");
  Cell cell;
  const std::string e = input_error_of([&] { cell_keys().read(c.section("cell"), cell); });
  EXPECT_THAT(e, HasSubstr("cell.time_step"));
  EXPECT_THAT(e, HasSubstr("(0, 62.5] s"));
  const auto ok = Config::from_string("[cell]\ntime_step = 62.5\n", "cell.toml");
  EXPECT_NO_THROW(cell_keys().read(ok.section("cell"), cell));
}

TEST(KeyTable, AnUnknownChoiceNamesTheAllowedOnes) {
  const auto c = Config::from_string("[cell]\ntrack = \"round\"\n", "cell.toml");
  Cell cell;
  const std::string e = input_error_of([&] { cell_keys().read(c.section("cell"), cell); });
  EXPECT_THAT(e, HasSubstr("not a known choice"));
  EXPECT_THAT(e, HasSubstr("\"averaged\", \"resolved\""));
}

TEST(KeyTable, TheSchemaListsEveryKeyWithItsDefaultFromTheInitializer) {
  const auto schema = cell_keys().schema("cell");
  ASSERT_EQ(schema.size(), cell_keys().keys().size());
  const auto row = [&](const std::string& key) {
    for (const auto& r : schema)
      if (r.key == key) return r;
    return KeySpec{};
  };
  const KeySpec size = row("cell.size");
  EXPECT_EQ(size.type, "number");
  EXPECT_EQ(size.range, "> 0");
  EXPECT_EQ(size.unit, "m");
  EXPECT_EQ(size.fallback, "0.002");
  EXPECT_EQ(size.doc, "side of the cell");
  EXPECT_EQ(row("cell.grid").fallback, "128");
  EXPECT_EQ(row("cell.grid").range, "[8, 4096]");
  EXPECT_EQ(row("cell.periodic").fallback, "true");
  EXPECT_EQ(row("cell.track").range, "averaged | resolved");
  EXPECT_EQ(row("cell.track").fallback, "averaged");
  EXPECT_EQ(row("cell.time_step").range, "(0, distance/velocity]");
  EXPECT_EQ(row("cell.integrator").fallback, "adaptive on an averaged track, else explicit");
  EXPECT_EQ(row("cell.tolerance").fallback, "1e-10");
  EXPECT_EQ(row("cell.tolerance").unit, "1");
}

TEST(KeyTable, EveryDeclaredKeyIsReadAndAnUndeclaredOneIsRefusedWithTheClosest) {
  const auto empty = Config::from_string("[cell]\n", "cell.toml");
  Cell cell;
  cell_keys().read(empty.section("cell"), cell);
  for (const auto& k : cell_keys().schema("cell")) EXPECT_TRUE(empty.applied_defaults().contains(k.key)) << k.key;

  const auto c = Config::from_string("[cell]\ngrid = 64\ntime_stpe = 0.01\n", "cell.toml");
  cell_keys().read(c.section("cell"), cell);
  const std::string e = input_error_of([&] { c.reject_unknown_keys(); });
  EXPECT_THAT(e, HasSubstr("cell.time_stpe"));
  EXPECT_THAT(e, HasSubstr("did you mean 'time_step'?"));
}

TEST(KeyTable, ARequiredKeyAndAConditionalOne) {
  struct Layer {
    std::string material;
    double thickness = 0.0;
  };
  const auto table = KeyTable<Layer>()
                         .string("material", &Layer::material, "layer material")
                         .required()
                         .number("thickness", &Layer::thickness, Range::non_negative(), units::length, "thickness")
                         .required()
                         .read_if([](const Config& c, const Layer&) { return c.has("material"); });
  Layer layer;
  EXPECT_THAT(input_error_of([&] { table.read(Config::from_string("", "l.toml"), layer); }),
              HasSubstr("missing required string"));
  EXPECT_THAT(input_error_of([&] { table.read(Config::from_string("material = \"SiO2\"", "l.toml"), layer); }),
              HasSubstr("missing required number"));
  table.read(Config::from_string("material = \"SiO2\"\nthickness = \"1 um\"", "l.toml"), layer);
  EXPECT_DOUBLE_EQ(layer.thickness, 1e-6);
  EXPECT_EQ(table.schema()[0].fallback, "");
  EXPECT_THROW(table.key("thickness_"), std::logic_error);
}

TEST(KeyTable, AKeyRequiredByTheKeysBeforeItAndAListOfValuesAsText) {
  struct Named {
    std::string default_name;  // not a key
    std::string name;
    std::vector<std::string> values;
  };
  const auto table = KeyTable<Named>()
                         .string("name", &Named::name, "name")
                         .computed_text([](const Named& n) { return n.default_name; }, "the study's")
                         .required_when([](const Named& n) { return n.default_name.empty(); })
                         .texts("values", &Named::values, "values");
  Named with_default{.default_name = "contact", .name = {}, .values = {}};
  const auto c = Config::from_string("values = [1, \"8 mm/s\"]", "n.toml");
  table.read(c, with_default);
  EXPECT_EQ(with_default.name, "contact");
  EXPECT_EQ(with_default.values, (std::vector<std::string>{"1", "8 mm/s"}));
  Named without;
  EXPECT_THAT(input_error_of([&] { table.read(c, without); }), HasSubstr("missing required string"));
  EXPECT_EQ(table.schema()[0].fallback, "the study's");
  EXPECT_EQ(table.schema()[1].type, "list");
}

TEST(KeyTable, ListsOfNumbersAndOfNamesKeepTheirInitializerWhenAbsent) {
  struct Runs {
    std::vector<double> pressures{1e9, 2e9};
    std::vector<std::string> amorphous;
  };
  const auto table = KeyTable<Runs>()
                         .numbers("pressures", &Runs::pressures, Range::non_negative(), units::pressure, "p_N")
                         .names("amorphous", &Runs::amorphous, "amorphous materials");
  Runs absent;
  const auto none = Config::from_string("", "r.toml");
  table.read(none, absent);
  EXPECT_EQ(absent.pressures, (std::vector<double>{1e9, 2e9}));
  EXPECT_TRUE(absent.amorphous.empty());
  EXPECT_NO_THROW(none.reject_unknown_keys());
  const auto read = none.keys_read();
  EXPECT_EQ(read.size(), 2u) << "both are read, to be suggested for a misspelt one";

  Runs given;
  table.read(Config::from_string("pressures = [\"0 GPa\", 4e9]\namorphous = \"Si\"", "r.toml"), given);
  EXPECT_EQ(given.pressures, (std::vector<double>{0.0, 4e9}));
  EXPECT_EQ(given.amorphous, (std::vector<std::string>{"Si"}));
  table.read(Config::from_string("amorphous = [\"Si\", \"SiO2\"]", "r.toml"), given);
  EXPECT_EQ(given.amorphous, (std::vector<std::string>{"Si", "SiO2"}));

  const std::string empty = input_error_of([&] { table.read(Config::from_string("pressures = []", "r.toml"), given); });
  EXPECT_THAT(empty, HasSubstr("r.toml"));
  EXPECT_THAT(empty, HasSubstr("pressures"));
  EXPECT_THAT(empty, HasSubstr("an empty list"));
  EXPECT_THAT(empty, HasSubstr("≥ 0 Pa"));
  EXPECT_THAT(input_error_of([&] { table.read(Config::from_string("pressures = [\"1 m\"]", "r.toml"), given); }),
              HasSubstr("pressures"));
  EXPECT_THAT(input_error_of([&] { table.read(Config::from_string("amorphous = 3", "r.toml"), given); }),
              HasSubstr("not a list of names"));

  const auto schema = table.schema("nano");
  EXPECT_EQ(schema[0].type, "list");
  EXPECT_EQ(schema[0].unit, "Pa");
  EXPECT_EQ(schema[0].fallback, "[1000000000, 2000000000]");
  EXPECT_EQ(schema[1].fallback, "[]");
}

TEST(KeyTable, AnOptionalNumberAComputedIntegerAndAKeyWithItsOwnReader) {
  struct Run {
    std::optional<double> working_pressure;
    int jobs = 1;
    std::string potential;
  };
  const auto table =
      KeyTable<Run>()
          .optional_number("working_pressure", &Run::working_pressure, Range::positive(), units::pressure, "p_work")
          .fallback("p_crit")
          .integer("jobs", &Run::jobs, Range::closed(1, 256), "threads")
          .computed_default([](const Run&) { return 3.0; }, "the threads")
          .custom("potential", "path", "a file name", "", "potential file",
                  [](const Config& c, const std::string& key, Run& r) {
                    if (c.has(key)) r.potential = "found:" + c.string(key);
                  })
          .fallback("the material's")
          .allowed("a file beside the case, or in LAMMPS' folder");
  Run absent;
  table.read(Config::from_string("", "r.toml"), absent);
  EXPECT_FALSE(absent.working_pressure.has_value());
  EXPECT_EQ(absent.jobs, 3);
  EXPECT_EQ(absent.potential, "");
  Run given;
  table.read(Config::from_string("working_pressure = \"2 GPa\"\njobs = 2\npotential = \"Si.sw\"", "r.toml"), given);
  EXPECT_EQ(given.working_pressure.value_or(0.0), 2e9);
  EXPECT_EQ(given.jobs, 2);
  EXPECT_EQ(given.potential, "found:Si.sw");
  EXPECT_THAT(input_error_of([&] { table.read(Config::from_string("working_pressure = 0", "r.toml"), given); }),
              HasSubstr("> 0"));
  const auto schema = table.schema();
  EXPECT_EQ(schema[0].fallback, "p_crit");
  EXPECT_EQ(schema[0].unit, "Pa");
  EXPECT_EQ(schema[1].fallback, "the threads");
  EXPECT_EQ(schema[2].type, "path");
  EXPECT_EQ(schema[2].range, "a file beside the case, or in LAMMPS' folder");
  EXPECT_EQ(schema[2].fallback, "the material's");
}
