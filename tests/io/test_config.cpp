// Case files: typed getters with ranges and units; every kind of bad input
// is an InputError that names the file, the key, the value and what is allowed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "input_error_of.hpp"

#include <cmath>
#include <limits>

#include <fstream>

#include <nlohmann/json.hpp>

#include "wearscale/io/config.hpp"

using namespace wearscale;
using ::testing::AllOf;
using ::testing::HasSubstr;

namespace {
const char* kCase = R"(
[case]
name = "demo"

[scale.macro]
backend = "hertz"
grid = 128
size = 2e-3
velocity = "8 mm/s"
load = 1
layer = { material = "SiO2", thickness = "1 um" }
loads = [0.5, 1, "2 N"]
flag = true
)";

}  // namespace

TEST(Config, TypedGettersReadValuesInSI) {
  const auto c = Config::from_string(kCase, "demo.toml");
  const auto m = c.section("scale.macro");
  EXPECT_EQ(m.integer("grid", Range::at_least(2)), 128);
  EXPECT_DOUBLE_EQ(m.number("size", Range::positive(), units::length), 2e-3);
  EXPECT_DOUBLE_EQ(m.number("velocity", Range::positive(), units::velocity), 8e-3);
  EXPECT_DOUBLE_EQ(m.number("load", Range::positive(), units::force), 1.0);  // integer accepted as a number
  EXPECT_DOUBLE_EQ(m.number("layer.thickness", Range::non_negative(), units::length), 1e-6);
  EXPECT_EQ(m.string("layer.material"), "SiO2");
  EXPECT_TRUE(m.boolean("flag"));
  EXPECT_EQ(m.numbers("loads", Range::positive(), units::force), (std::vector<double>{0.5, 1.0, 2.0}));
  EXPECT_EQ(c.keys("scale"), std::vector<std::string>{"macro"});
}

TEST(Config, OptionalGettersFallBackOnlyWhenTheKeyIsAbsent) {
  const auto c = Config::from_string(kCase, "demo.toml");
  EXPECT_EQ(c.integer_or("scale.macro.steps", 10, Range::at_least(1)), 10);
  EXPECT_EQ(c.integer_or("scale.macro.grid", 10, Range::at_least(1)), 128);
  EXPECT_THAT(input_error_of([&] { c.integer_or("scale.macro.grid", 10, Range::at_most(64)); }), HasSubstr("out of range"));
}

TEST(Config, OutOfRangeNamesFileLineKeyValueAndRange) {
  const auto c = Config::from_string(kCase, "demo.toml");
  const auto msg = input_error_of([&] { c.integer("scale.macro.grid", Range::closed(2, 64)); });
  EXPECT_THAT(msg, HasSubstr("demo.toml:7"));
  EXPECT_THAT(msg, HasSubstr("scale.macro.grid"));
  EXPECT_THAT(msg, HasSubstr("128"));
  EXPECT_THAT(msg, HasSubstr("[2, 64]"));
}

TEST(Config, AnIntegerTooLargeForADoubleIsANumberTheRangeJudges) {
  // 2^53 + 1 and beyond have no exact double: read as the nearest one (the
  // fuzzer found k_r = 499999999999999999 ending the program instead).
  const auto c = Config::from_string("k_r = 499999999999999999\nk_s = 9007199254740993\n", "big.toml");
  EXPECT_DOUBLE_EQ(c.number("k_s"), 9007199254740992.0);
  const auto msg = input_error_of([&] { c.number("k_r", Range::closed(1, 1e6)); });
  EXPECT_THAT(msg, HasSubstr("big.toml:1"));
  EXPECT_THAT(msg, HasSubstr("k_r"));
  EXPECT_THAT(msg, HasSubstr("out of range"));
}

TEST(Config, WrongTypeIsReportedWithTheTypeFound) {
  const auto c = Config::from_string(kCase, "demo.toml");
  EXPECT_THAT(input_error_of([&] { c.integer("scale.macro.size"); }), HasSubstr("expected an integer, got a float"));
  EXPECT_THAT(input_error_of([&] { c.number("scale.macro.backend"); }), HasSubstr("cannot read a quantity"));
  EXPECT_THAT(input_error_of([&] { c.string("scale.macro.grid"); }), HasSubstr("expected a string, got an integer"));
  EXPECT_THAT(input_error_of([&] { c.boolean("scale.macro.grid"); }), HasSubstr("scale.macro.grid"));
}

TEST(Config, UnitOfTheWrongDimensionIsRejected) {
  const auto c = Config::from_string(kCase, "demo.toml");
  const auto msg = input_error_of([&] { c.number("scale.macro.velocity", Range::positive(), units::pressure); });
  EXPECT_THAT(msg, HasSubstr("has unit of m/s, expected Pa"));
}

TEST(Config, MissingRequiredKeyIsNamed) {
  const auto c = Config::from_string(kCase, "demo.toml");
  EXPECT_THAT(input_error_of([&] { c.number("scale.macro.radius", Range::positive(), units::length); }),
              HasSubstr("key 'scale.macro.radius': missing required number"));
}

TEST(Config, ChoiceListsTheAllowedValues) {
  const auto c = Config::from_string(kCase, "demo.toml");
  EXPECT_EQ(c.choice("scale.macro.backend", {"hertz", "bem"}), "hertz");
  EXPECT_THAT(input_error_of([&] { c.choice("scale.macro.backend", {"bem", "dem"}); }), HasSubstr("\"bem\", \"dem\""));
}

TEST(Config, NaNIsNeverInRangeAndInfinityOnlyWhenAllowed) {
  const auto c = Config::from_string("a = nan\nb = inf\nc = \"inf\"\n", "x.toml");
  EXPECT_THROW(c.number("a"), InputError);
  EXPECT_THROW(c.number("b", Range::non_negative()), InputError);
  EXPECT_TRUE(std::isinf(c.number("b", Range::non_negative().or_infinite())));
  EXPECT_TRUE(std::isinf(c.number("c", Range::non_negative().or_infinite(), units::dimensionless)));
}

TEST(Config, UnknownKeysAreErrorsWithASuggestion) {
  auto c = Config::from_string(kCase + std::string("gird = 3\n"), "demo.toml");
  const auto m = c.section("scale.macro");
  c.string("case.name");
  m.string("backend");
  m.integer("grid");
  m.mark_used("size");
  m.mark_used("velocity");
  m.mark_used("load");
  m.mark_used("layer");
  m.mark_used("loads");
  m.mark_used("flag");
  const auto msg = input_error_of([&] { c.reject_unknown_keys(); });
  EXPECT_THAT(msg, HasSubstr("scale.macro.gird"));
  EXPECT_THAT(msg, HasSubstr("did you mean 'grid'?"));
}

TEST(Config, AllKeysReadMeansNoError) {
  const auto c = Config::from_string("[a]\nx = 1\ny = { z = 2 }\n", "ok.toml");
  c.number("a.x");
  c.number("a.y.z");
  EXPECT_NO_THROW(c.reject_unknown_keys());
}

TEST(Config, SyntaxErrorsGiveFileAndLine) {
  const auto msg = input_error_of([] { Config::from_string("[case]\nname = \"x\"\ngrid = = 3\n", "bad.toml"); });
  EXPECT_THAT(msg, HasSubstr("bad.toml:3"));
  EXPECT_THAT(msg, HasSubstr("TOML syntax error"));
}

TEST(Config, MissingFileIsBadInput) {
  EXPECT_THAT(input_error_of([] { Config::load("/nonexistent/case.toml"); }), HasSubstr("/nonexistent/case.toml: no such case file"));
}

TEST(Config, LoadReadsAFile) {
  const auto path = std::filesystem::temp_directory_path() / "wearscale_config_test.toml";
  std::ofstream(path) << kCase;
  const auto c = Config::load(path);
  EXPECT_EQ(c.string("case.name"), "demo");
  EXPECT_EQ(c.source(), path.string());
  std::filesystem::remove(path);
}

TEST(Config, OverridesReplaceCreateAndAreTyped) {
  auto c = Config::from_string(kCase, "demo.toml");
  c.override_value("scale.macro.grid=64");
  c.override_value("scale.macro.velocity = 1 cm/s");  // bare words become a string
  c.override_value("scale.nano.backend=analytic");
  c.override_value("materials.layer.thickness=inf");
  EXPECT_EQ(c.integer("scale.macro.grid"), 64);
  EXPECT_DOUBLE_EQ(c.number("scale.macro.velocity", Range::positive(), units::velocity), 0.01);
  EXPECT_EQ(c.string("scale.macro.backend"), "hertz");
  EXPECT_TRUE(std::isinf(c.number("materials.layer.thickness", Range::non_negative().or_infinite())));
  EXPECT_THAT(input_error_of([&] { c.integer("scale.macro.grid", Range::at_least(128)); }), HasSubstr("--set"));
}

TEST(Config, MalformedOverridesAreBadInput) {
  auto c = Config::from_string(kCase, "demo.toml");
  EXPECT_THAT(input_error_of([&] { c.override_value("scale.macro.grid"); }), HasSubstr("expected KEY=VALUE"));
  EXPECT_THAT(input_error_of([&] { c.override_value("scale.macro.grid.sub=1"); }), HasSubstr("not a table"));
  EXPECT_THAT(input_error_of([&] { c.override_value("scale..grid=1"); }), HasSubstr("empty component"));
}

// Found by fuzz_sweep: a --set value with a byte that is not UTF-8 became a
// bare string that no JSON output (the case fingerprint) can hold.
TEST(Config, OverridesThatAreNotUtf8AreBadInputAndChangeNothing) {
  auto c = Config::from_string(kCase, "demo.toml");
  EXPECT_THAT(input_error_of([&] { c.override_value("scale.macro.backend=her\xFBtz"); }),
              AllOf(HasSubstr("not valid UTF-8"), HasSubstr("scale.macro.backend")));
  EXPECT_THAT(input_error_of([&] { c.override_value("scale.\xC3=1"); }), HasSubstr("not valid UTF-8"));
  EXPECT_EQ(c.string("scale.macro.backend"), "hertz");
  c.override_value("scale.macro.label=\xC3\xA9t\xC3\xA9");  // "été" is UTF-8
  EXPECT_EQ(c.to_json()["scale"]["macro"]["label"], "\xC3\xA9t\xC3\xA9");
}

TEST(Config, ResolvedCaseRoundTripsToJsonAndToml) {
  auto c = Config::from_string(kCase, "demo.toml");
  c.override_value("scale.macro.grid=32");
  const auto j = c.to_json();
  EXPECT_EQ(j["scale"]["macro"]["grid"], 32);
  EXPECT_EQ(c.section("scale.macro").to_json()["backend"], "hertz");
  const auto again = Config::from_string(c.to_toml(), "again");
  EXPECT_EQ(again.integer("scale.macro.grid"), 32);
}

// A bound computed from other inputs (3 d0 with d0 = "6 nm", read as
// 6 × 1e-9) rounds one ulp above what a user types for it (1.8e-8): the
// typed value is accepted, as the bound. Values really outside, and open
// bounds, are not moved.
TEST(Config, AValueTypedAtAComputedBoundIsAcceptedAsTheBound) {
  const auto c = Config::from_string("d0 = \"6 nm\"\na = \"18 nm\"\nb = 1.8e-8\nc = 1.7999e-8\nd = 0.5", "t.toml");
  const double bound = 3.0 * c.number("d0", Range::positive(), units::length);
  ASSERT_GT(bound, 1.8e-8) << "the product rounds above 1.8e-8";
  EXPECT_EQ(c.number("a", Range::at_least(bound), units::length), bound);
  EXPECT_EQ(c.number("b", Range::at_least(bound), units::length), bound);
  EXPECT_THROW(c.number("c", Range::at_least(bound), units::length), InputError);
  EXPECT_THROW(c.number("b", Range::greater_than(bound), units::length), InputError);
  EXPECT_EQ(c.number("d", Range::closed(0.0, 0.5)), 0.5);
}

// Collecting (a check, a run's preparation): the errors that do not depend on each other are
// recorded, a valid value stands in for each, and they are raised together, numbered.
TEST(Config, IndependentErrorsAreCollectedAndRaisedTogether) {
  const auto c = Config::from_string("[a]\nx = -1\ny = \"fast\"\nn = 0\nz = \"3 kg\"\nq = 1\n", "demo.toml");
  c.collect_errors(true);
  EXPECT_EQ(c.number("a.x", Range::closed(0.0, 2.0)), 0.0);                // the nearest allowed value
  EXPECT_EQ(c.choice_or("a.y", "slow", {"slow", "medium"}), "slow");         // the default
  EXPECT_EQ(c.integer("a.n", Range::at_least(1)), 1);
  EXPECT_EQ(c.number_or("a.z", 5.0, Range::any(), units::length), 5.0);      // a unit of the wrong dimension
  EXPECT_GT(c.number("a.q", Range::positive()), 0.0);
  EXPECT_TRUE(c.has_collected_errors());
  const auto msg = input_error_of([&] { c.reject_unknown_keys(); });
  EXPECT_THAT(msg, HasSubstr("demo.toml: 4 errors in the case:"));
  EXPECT_THAT(msg, HasSubstr("1. demo.toml:2: key 'a.x' = -1: out of range; allowed: [0, 2]"));
  EXPECT_THAT(msg, HasSubstr("2. demo.toml:3: key 'a.y' = \"fast\": not a known choice"));
  EXPECT_THAT(msg, HasSubstr("3. demo.toml:4: key 'a.n' = 0: out of range"));
  EXPECT_THAT(msg, HasSubstr("4. demo.toml:5: key 'a.z' = \"3 kg\": has unit of"));
  EXPECT_FALSE(c.has_collected_errors());
  EXPECT_THROW(c.number("a.x", Range::closed(0.0, 2.0)), InputError);  // collecting stopped: the first error throws
}

TEST(Config, UnknownKeysAreAllListed) {
  const auto c = Config::from_string("[a]\nx = 1\nxx = 2\n[b]\ny = 3\n", "demo.toml");
  c.number("a.x");
  const auto msg = input_error_of([&] { c.reject_unknown_keys(); });
  EXPECT_THAT(msg, HasSubstr("2 errors in the case"));
  EXPECT_THAT(msg, HasSubstr("key 'a.xx' = 2: unknown key"));
  EXPECT_THAT(msg, HasSubstr("key 'b.y' = 3: unknown key"));
}

TEST(Config, AnErrorAfterTheCollectedOnesIsListedLastAsPossiblyFollowingFromThem) {
  const auto c = Config::from_string("[a]\nx = -1\n", "demo.toml");
  c.collect_errors(true);
  c.number("a.x", Range::non_negative());
  const std::string msg = c.collected_with("demo.toml: key 'a.w': missing").what();
  EXPECT_THAT(msg, HasSubstr("2 errors in the case"));
  EXPECT_THAT(msg, HasSubstr("2. demo.toml: key 'a.w': missing (found with the values in error above replaced"));
}

TEST(Config, TheDefaultsAGetterAppliesAreRecordedBesideTheCase) {
  const auto c = Config::from_string("[a]\nx = 1\n", "demo.toml");
  c.number("a.x");
  c.number_or("a.y", 2.5);
  c.integer_or("b.n", 7);
  c.boolean_or("b.on", true);
  c.string_or("a.name", "z");
  c.number_or("a.big", std::numeric_limits<double>::infinity());
  c.number_or("a.x", 9.0);  // given: not a default
  const auto j = c.to_json_with_defaults();
  EXPECT_EQ(j["a"]["x"], 1);
  EXPECT_EQ(j["a"]["y"], 2.5);
  EXPECT_EQ(j["b"]["n"], 7);
  EXPECT_EQ(j["b"]["on"], true);
  EXPECT_EQ(j["a"]["big"], "inf");
  EXPECT_EQ(c.applied_defaults().size(), 5u);
  EXPECT_FALSE(c.applied_defaults().contains("a.x"));
  EXPECT_FALSE(c.to_json()["a"].contains("y"));  // the case itself (its fingerprint) is unchanged
}

TEST(Config, AStopAfterTheWholeCaseIsCheckedIsNotAnError) {
  const auto c = Config::from_string("[a]\nx = 1\n", "demo.toml");
  c.number("a.x");
  c.stop_when_checked(true);
  EXPECT_NO_THROW(c.section("a").reject_unknown_keys());  // a part of the case: not the whole
  EXPECT_THROW(c.reject_unknown_keys(), CaseChecked);
  EXPECT_TRUE(c.fully_checked());
}

// A case's shape is bounded when it is read: 32 levels of tables, arrays and
// inline tables, keys of 1024 bytes (a 20 000-level table path used to take
// minutes, cubic in its depth); --set keys and values alike.
TEST(Config, ACaseNestedDeeperThanItsBoundIsRefusedWhenRead) {
  std::string path = "a";
  for (int k = 1; k < 20000; ++k) path += ".a";
  EXPECT_THAT(input_error_of([&] { (void)Config::from_string("[" + path + "]\nx = 1\n", "deep.toml"); }),
              AllOf(HasSubstr("deep.toml:1: tables and arrays nested more than 32 deep"), HasSubstr("allowed:")));
  EXPECT_THAT(input_error_of([&] {
                (void)Config::from_string("v = " + std::string(40, '[') + "1" + std::string(40, ']') + "\n", "arr.toml");
              }),
              HasSubstr("nested more than 32 deep"));
  EXPECT_THAT(input_error_of([&] { (void)Config::from_string(std::string(2000, 'k') + " = 1\n", "long.toml"); }),
              HasSubstr("a key of more than 1024 bytes"));
  std::string ok = "a";
  for (int k = 1; k < 30; ++k) ok += ".a";
  Config cfg = Config::from_string("[" + ok + "]\nx = 1\n", "ok.toml");  // 31 levels: within
  EXPECT_TRUE(cfg.has(ok + ".x"));
  EXPECT_THAT(input_error_of([&] { cfg.override_value(path + "=1"); }), HasSubstr("allowed: keys of at most"));
  EXPECT_THAT(input_error_of([&] { cfg.override_value("b=" + std::string(40, '[') + "1" + std::string(40, ']')); }),
              HasSubstr("nested more than 32 deep"));
}

// "inf" as text is TOML's inf: infinite whatever the key's dimension, judged by its range (a bulk layer).
TEST(Config, InfAsTextIsInfinityThatTheRangeJudges) {
  const Config cfg = Config::from_string("[l]\nt = \"inf\"\nn = \"-inf\"\n", "inf.toml");
  EXPECT_EQ(cfg.number("l.t", Range::non_negative().or_infinite(), units::length), HUGE_VAL);
  EXPECT_THAT(input_error_of([&] { (void)cfg.number("l.t", Range::non_negative(), units::length); }),
              HasSubstr("out of range"));
  EXPECT_THAT(input_error_of([&] { (void)cfg.number("l.n", Range::non_negative().or_infinite(), units::length); }),
              HasSubstr("out of range"));
}
