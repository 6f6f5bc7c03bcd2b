// A study that exists only in a test build: the Hertz contact of a sphere on
// a flat, a = (3FR/4E*)^(1/3) (§8.1). This file is the only source that
// names it; test_one_file_study.cpp checks that every front end shows and
// runs it.
#include <cmath>

#include "wearscale/core/units.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {
namespace {

class HertzStudy final : public Study {
 public:
  std::string name() const override { return "hertz"; }
  std::string summary() const override { return "Hertz contact radius of a sphere on an elastic flat (§8.1)"; }
  Schema schema() const override {
    return {{"hertz.load", "number", "> 0", "N", "", "normal force F", "--load"},
            {"hertz.radius", "number", "> 0", "m", "", "sphere radius R", "--radius"},
            {"hertz.e_star", "number", "> 0", "Pa", "", "contact modulus E* (1.12)", "--e-star"}};
  }
  void run(const Config& config, RunContext& context) override {
    const Config c = config.section("hertz");
    const double f = c.number("load", Range::positive(), units::force);
    const double r = c.number("radius", Range::positive(), units::length);
    const double e_star = c.number("e_star", Range::positive(), units::pressure);
    config.reject_unknown_keys();
    context.report("contact_radius", std::cbrt(3.0 * f * r / (4.0 * e_star)), "m", "a = (3FR/4E*)^(1/3)");
  }
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(HertzStudy)
