// nano/analytic: the junction model of §7.1.2 on the molecular strengths —
// an InterfaceLaw (p_crit (7.5), μ0 (9.13), A/A0 (7.6), wear rate (9.21))
// for each interface the pin meets: the disc, and its oxide layer if any —
// and the critical junction size d* (4.35) of the material that governs it,
// with the junction's strength σ_max(p_crit) = p_crit.
#include <map>

#include "wearscale/coupling/scale.hpp"
#include "backends/case_materials.hpp"
#include "wearscale/materials/junction_model.hpp"
#include "wearscale/materials/material.hpp"

namespace wearscale::coupling {

namespace {

class NanoAnalytic final : public Scale {
 public:
  static inline const Ports ports{{{Quantity::ShearStrength, "pin, disc, layer"}},
                                  {{Quantity::InterfaceLaw, "pin/disc"}, {Quantity::InterfaceLaw, "pin/layer"}}};

  explicit NanoAnalytic(const ScaleSetup& setup) : provenance_(setup.provenance()) {
    const Config& root = setup.root;
    const auto library = material_library(root);
    case_materials(root, library);  // checks every name
    pin_ = root.string("materials.pin");
    counterfaces_.push_back(root.string("materials.disc"));
    if (root.has("materials.layer.material")) {
      const std::string layer = root.string("materials.layer.material");
      if (layer != counterfaces_.front()) counterfaces_.push_back(layer);
    }
    e_star_ = materials::effective_modulus(library.get(pin_), library.get(pin_));
    for (const auto& m : case_materials(root, library)) records_.emplace(m, library.get(m));
  }

  std::vector<Key> consumes() const override {
    std::vector<Key> out{{ports.consumes[0].what, pin_}};
    for (const auto& c : counterfaces_)
      if (c != pin_) out.push_back({ports.consumes[0].what, c});
    return out;
  }
  std::vector<Key> provides() const override {
    std::vector<Key> out;
    for (const auto& c : counterfaces_) out.push_back({ports.provides[0].what, pin_ + "/" + c});
    return out;
  }

  void run(Exchange& exchange, RunContext& ctx) override {
    const auto& pin_law = exchange.get<Quantity::ShearStrength>(pin_);
    for (const auto& c : counterfaces_) {
      const auto& law = exchange.get<Quantity::ShearStrength>(c);
      const auto interface = materials::interface_law(pin_, pin_law, c, law);
      const std::string tag = pin_ + "-" + c;
      ctx.report("p_crit_" + tag, interface.p_crit, "Pa",
                 "critical pressure of the " + interface.pair + " junctions, governed by " + interface.governing + " (7.5)");
      ctx.report("mu0_" + tag, interface.mu0, "1", "steady friction coefficient of " + interface.pair + " (9.13)");
      ctx.report("steady_slope_" + tag, materials::steady_slope_rms(interface.p_crit, e_star_), "1",
                 "steady RMS slope √(2π) p_crit/E* with E* of the pin material (9.17)");
      ctx.report("d_star_" + tag,
                 materials::critical_size(records_.at(interface.governing), interface.p_crit,
                                          materials::JunctionGeometry::FlatCircular),
                 "m",
                 "critical junction size 12πγG/((2−ν)σ²) of " + interface.governing +
                     " at the junction strength σ_max(p_crit) = p_crit (4.35)");
      exchange.put<Quantity::InterfaceLaw>(interface.pair, interface, provenance_);
    }
  }

 private:
  Provenance provenance_;
  std::string pin_;
  std::vector<std::string> counterfaces_;
  double e_star_ = 0.0;
  std::map<std::string, materials::Material> records_;
};

}  // namespace

WEARSCALE_BACKEND(nano_analytic) {
  registry.add<NanoAnalytic>("nano", "analytic",
                             "junction model of §7.1.2: p_crit, μ0, A/A0 and wear rate per interface",
                             [] { return Schema{}; });  // reads [materials] only
}

}  // namespace wearscale::coupling
