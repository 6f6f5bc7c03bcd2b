// The backend registry: named factories per scale kind; unknown names are bad
// input that lists what exists.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "wearscale/core/registry.hpp"

using namespace wearscale;
using ::testing::HasSubstr;

namespace {
struct Model {
  virtual ~Model() = default;
  virtual double value() const = 0;
};
struct Constant : Model {
  explicit Constant(double v) : v_(v) {}
  double value() const override { return v_; }
  double v_;
};
using ModelRegistry = Registry<Model, double>;

ModelRegistry make() {
  ModelRegistry r;
  r.add({"nano", "analytic", "junction model", {"ShearStrength"}, {"InterfaceLaw"}},
        [](double x) { return std::make_unique<Constant>(x); });
  r.add({"nano", "dem", "sheared junctions", {"ShearStrength"}, {"InterfaceLaw"}},
        [](double x) { return std::make_unique<Constant>(2 * x); });
  r.add({"macro", "hertz", "closed form", {}, {"MacroResult"}},
        [](double x) { return std::make_unique<Constant>(-x); });
  return r;
}
}  // namespace

TEST(Registry, CreatesTheRegisteredBackendWithItsArguments) {
  const auto r = make();
  EXPECT_EQ(r.create("nano", "dem", 1.5)->value(), 3.0);
  EXPECT_EQ(r.create("macro", "hertz", 1.0)->value(), -1.0);
}

TEST(Registry, ListsBackendsSortedByKindThenName) {
  const auto list = make().list();
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(list[0].id(), "macro/hertz");
  EXPECT_EQ(list[1].id(), "nano/analytic");
  EXPECT_EQ(list[2].id(), "nano/dem");
  EXPECT_EQ(list[1].provides, std::vector<std::string>{"InterfaceLaw"});
  EXPECT_EQ(make().kinds(), (std::vector<std::string>{"macro", "nano"}));
}

TEST(Registry, UnknownBackendListsTheKnownOnes) {
  const auto r = make();
  try {
    r.create("nano", "md", 1.0);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown nano backend 'md'"));
    EXPECT_THAT(e.what(), HasSubstr("analytic, dem"));
  }
  EXPECT_THROW(r.create("meso", "x", 1.0), InputError);
}

TEST(Registry, RegisteringTwiceIsAProgrammingError) {
  auto r = make();
  EXPECT_THROW(r.add({"nano", "dem", "", {}, {}}, [](double) { return std::unique_ptr<Model>(); }), std::logic_error);
}
