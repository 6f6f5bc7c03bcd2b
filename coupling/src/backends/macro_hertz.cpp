// macro/hertz: the unworn pin of the pin-on-disc test as a Hertz contact
// (§8.1: contact diameter 78.2 µm at F = 1 N, R = 3 mm, SiO2 on SiO2).
// The closed form is the reference the BEM pin-on-disc model starts from.
#include <vector>

#include "wearscale/bem/hertz.hpp"
#include "wearscale/coupling/scale.hpp"
#include "wearscale/io/key_table.hpp"
#include "wearscale/io/csv.hpp"

namespace wearscale::coupling {

namespace {

// The keys of [scale.macro] with backend = "hertz".
struct HertzKeys {
  double pin_radius = 0.0, normal_load = 0.0;
  // Both bodies share one material here, as in the thesis' contact solve (§9.3.2).
  double elastic_modulus = 0.0, poisson_ratio = 0.0;
  std::size_t profile_points = 201;
};

const KeyTable<HertzKeys>& hertz_keys() {
  using K = HertzKeys;
  static const auto table =
      KeyTable<K>()
          .number("pin_radius", &K::pin_radius, Range::positive(), units::length, "pin radius R")
          .required()
          .number("normal_load", &K::normal_load, Range::positive(), units::force, "normal load F")
          .required()
          .number("elastic_modulus", &K::elastic_modulus, Range::positive(), units::pressure,
                  "Young's modulus E of both bodies")
          .required()
          .number("poisson_ratio", &K::poisson_ratio, Range::closed_open(-1.0, 0.5), "Poisson's ratio ν of both bodies")
          .required()
          .integer("profile_points", &K::profile_points, Range::at_least(3),
                   "points of the pressure profile, r from 0 to 1.5 a");
  return table;
}

class MacroHertz final : public Scale {
 public:
  static inline const Ports ports{{}, {{Quantity::MacroResult, "pin/disc"}}};

  explicit MacroHertz(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    HertzKeys k;
    hertz_keys().read(setup.section, k);
    contact_.radius = k.pin_radius;
    contact_.load = k.normal_load;
    contact_.e_star = bem::effective_modulus(k.elastic_modulus, k.poisson_ratio, k.elastic_modulus, k.poisson_ratio);
    points_ = k.profile_points;
  }

  std::vector<Key> consumes() const override { return ports.consumes; }
  std::vector<Key> provides() const override { return ports.provides; }

  void run(Exchange& exchange, RunContext& ctx) override {
    const double a = contact_.contact_radius();
    ctx.report("contact_radius", a, "m", "Hertz contact radius a = (3FR/4E*)^(1/3)");
    ctx.report("peak_pressure", contact_.peak_pressure(), "Pa", "Hertz peak pressure p0 = 3F/(2πa²)");
    ctx.report("mean_pressure", contact_.mean_pressure(), "Pa", "mean contact pressure F/(πa²)");
    ctx.report("approach", contact_.approach(), "m", "approach of distant points δ = a²/R");
    ctx.report("effective_modulus", contact_.e_star, "Pa", "E* of the pair (1.12)");

    std::vector<double> r(points_), p(points_);
    for (std::size_t k = 0; k < points_; ++k) {
      r[k] = 1.5 * a * static_cast<double>(k) / static_cast<double>(points_ - 1);
      p[k] = contact_.pressure(r[k]);
    }
    ctx.h5().write_table("/macro/hertz/profile", {"r", "pressure"}, {r, p}, {"m", "Pa"});
    const auto csv = ctx.output_dir() / "pressure_profile.csv";
    write_csv(csv, {"r", "pressure"}, {r, p}, {"m", "Pa"}, {"Hertz pressure profile of the unworn pin (macro/hertz)"});
    ctx.add_file(csv);
    exchange.put<Quantity::MacroResult>(provides().front().subject, ctx.results(), provenance_);
  }

 private:
  bem::HertzContact contact_{};
  std::size_t points_ = 201;
  Provenance provenance_;
};

}  // namespace

WEARSCALE_BACKEND(macro_hertz) {
  registry.add<MacroHertz>("macro", "hertz", "Hertz contact of the unworn pin on the disc (closed form, §8.1)",
                           [] { return hertz_keys().schema("scale.macro"); });
}

}  // namespace wearscale::coupling
