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
