// The pipeline orders scales by what they consume and provide, and refuses a
// case where a quantity has no provider, two providers, or a cycle.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "input_error_of.hpp"

#include "wearscale/core/errors.hpp"
#include "wearscale/coupling/pipeline.hpp"

#include <type_traits>

using namespace wearscale;
using namespace wearscale::coupling;
using ::testing::HasSubstr;

namespace {
const Key strength_si{Quantity::ShearStrength, "Si"};
const Key law{Quantity::InterfaceLaw, "SiO2/Si"};
const Key macro{Quantity::MacroResult, "pin/disc"};

// Each quantity's value (of its own type) carries one number through a chain of fake scales.
double number_of(const Exchange& ex, const Key& k) {
  switch (k.what) {
    case Quantity::ShearStrength: return ex.get<Quantity::ShearStrength>(k.subject).sigma_max(0.0);
    case Quantity::InterfaceLaw: return ex.get<Quantity::InterfaceLaw>(k.subject).mu0;
    case Quantity::MacroResult: return ex.get<Quantity::MacroResult>(k.subject).get<double>();
  }
  return 0.0;
}
void put_number(Exchange& ex, const Key& k, double x, const Provenance& p) {
  switch (k.what) {
    case Quantity::ShearStrength:
      ex.put<Quantity::ShearStrength>(k.subject, materials::StrengthLaw::constant(k.subject, x, 1e12, "test"), p);
      return;
    case Quantity::InterfaceLaw: ex.put<Quantity::InterfaceLaw>(k.subject, {k.subject, "", 1.0, x}, p); return;
    case Quantity::MacroResult: ex.put<Quantity::MacroResult>(k.subject, x, p); return;
  }
}

// A scale that records when it ran and provides numbers.
struct FakeScale : Scale {
  FakeScale(std::vector<Key> in, std::vector<Key> out, std::vector<std::string>* log, std::string id)
      : in_(std::move(in)), out_(std::move(out)), log_(log), id_(std::move(id)) {}
  std::vector<Key> consumes() const override { return in_; }
  std::vector<Key> provides() const override { return out_; }
  void run(Exchange& ex, RunContext&) override {
    double sum = 1.0;
    for (const auto& k : in_) sum += number_of(ex, k);
    for (const auto& k : out_) put_number(ex, k, sum, Provenance{"test", id_, {}});
    log_->push_back(id_);
  }
  std::vector<Key> in_, out_;
  std::vector<std::string>* log_;
  std::string id_;
};


struct PipelineTest : ::testing::Test {
  std::vector<std::string> ran;
  std::unique_ptr<Scale> scale(std::vector<Key> in, std::vector<Key> out, const std::string& id) {
    return std::make_unique<FakeScale>(std::move(in), std::move(out), &ran, id);
  }
};
}  // namespace

TEST_F(PipelineTest, RunsProvidersBeforeConsumersWhateverTheDeclarationOrder) {
  Pipeline p;
  p.add("macro/x", scale({law}, {macro}, "macro"));
  p.add("nano/x", scale({strength_si}, {law}, "nano"));
  p.add("molecular/x", scale({}, {strength_si}, "molecular"));
  p.order();
  EXPECT_EQ(p.ids(), (std::vector<std::string>{"molecular/x", "nano/x", "macro/x"}));

  const auto dir = std::filesystem::temp_directory_path() / "wearscale_pipeline_test";
  H5Writer h5(dir / "run.h5");
  RunContext ctx(dir, h5);
  Exchange ex;
  p.run(ex, ctx);
  EXPECT_EQ(ran, (std::vector<std::string>{"molecular", "nano", "macro"}));
  EXPECT_EQ(number_of(ex, macro), 3.0);  // 1 → 2 → 3 through the chain
  EXPECT_EQ(ex.provenance(law).backend, "nano");
}

TEST_F(PipelineTest, AMissingProviderNamesTheConsumerAndTheQuantity) {
  Pipeline p;
  p.add("macro/bem-pin-on-disc", scale({law}, {macro}, "macro"));
  const auto msg = input_error_of([&] { p.order(); });
  EXPECT_THAT(msg, HasSubstr("macro/bem-pin-on-disc needs InterfaceLaw(SiO2/Si)"));
}

TEST_F(PipelineTest, TwoProvidersOfOneQuantityAreRefused) {
  Pipeline p;
  p.add("nano/analytic", scale({}, {law}, "a"));
  p.add("nano/dem", scale({}, {law}, "b"));
  EXPECT_THAT(input_error_of([&] { p.order(); }), HasSubstr("provided by two scales, nano/analytic and nano/dem"));
}

TEST_F(PipelineTest, CyclesAreRefused) {
  Pipeline p;
  p.add("a/x", scale({law}, {strength_si}, "a"));
  p.add("b/x", scale({strength_si}, {law}, "b"));
  EXPECT_THAT(input_error_of([&] { p.order(); }), HasSubstr("cycle"));
}

// The type of each quantity is checked at compile time (get<Quantity::ShearStrength>
// returns a StrengthLaw; asking for another type does not compile), so only a
// missing or twice-provided key is left to check at run time.
TEST(Exchange, TypedAccessAndProvenance) {
  Exchange ex;
  ex.put<Quantity::ShearStrength>("Si", materials::StrengthLaw::constant("Si", 10.6e9, 1e12, "test"),
                                  Provenance{"molecular", "table", {{"file", "si.csv"}}});
  static_assert(std::is_same_v<decltype(ex.get<Quantity::ShearStrength>("Si")), const materials::StrengthLaw&>);
  EXPECT_EQ(ex.get<Quantity::ShearStrength>("Si").sigma_max(1e9), 10.6e9);
  EXPECT_EQ(ex.provenance(strength_si).parameters["file"], "si.csv");
  EXPECT_THROW(ex.get<Quantity::InterfaceLaw>("SiO2/Si"), std::logic_error);
  EXPECT_THROW(ex.put<Quantity::ShearStrength>("Si", materials::StrengthLaw::constant("Si", 1.0, 1e12, "test"), Provenance{}),
               std::logic_error);
  EXPECT_EQ(strength_si.to_string(), "ShearStrength(Si)");
}
