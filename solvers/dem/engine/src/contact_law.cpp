#include "wearscale/dem/contact_law.hpp"

#include <algorithm>
#include <initializer_list>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/registry.hpp"

namespace wearscale::dem {

namespace registered {
#define WEARSCALE_LAW(key) ContactLawEntry contact_law_##key();
#include "contact_laws.inc"
#undef WEARSCALE_LAW
}  // namespace registered

void ContactLaw::prepare(const Particles&, const NeighborList&) {}

namespace {
// What the registry shows of a law: its name (`[dem] law`) and one line.
struct ContactLawInfo {
  std::string name, doc;
  static std::string unknown(const std::string&, const std::string& name, const std::vector<std::string>&,
                             const std::vector<std::string>& known) {
    return fmt::format("unknown DEM contact law '{}'; allowed: {}", name, fmt::join(known, ", "));
  }
};
using ContactLawRegistry = NamedRegistry<ContactLawInfo, ContactLaw, const ContactLawInputs&>;

// The laws of the build in the one registry template (core/registry.hpp),
// each from its WEARSCALE_CONTACT_LAW line (collected by solvers/dem/CMakeLists.txt).
const ContactLawRegistry& registry() {
  static const ContactLawRegistry r = [] {
    ContactLawRegistry laws;
    for (const ContactLawEntry& e : {
#define WEARSCALE_LAW(key) registered::contact_law_##key(),
#include "contact_laws.inc"
#undef WEARSCALE_LAW
         })
      laws.add({e.name, e.doc}, e.make);
    return laws;
  }();
  return r;
}
}  // namespace

const std::vector<ContactLawEntry>& contact_laws() {
  static const std::vector<ContactLawEntry> table = [] {
    std::vector<ContactLawEntry> t{
#define WEARSCALE_LAW(key) registered::contact_law_##key(),
#include "contact_laws.inc"
#undef WEARSCALE_LAW
    };
    std::sort(t.begin(), t.end(), [](const auto& a, const auto& b) { return std::string_view(a.name) < b.name; });
    return t;
  }();
  return table;
}

std::vector<std::string> contact_law_names() { return registry().names(); }

std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const ContactLawInputs& inputs) {
  return registry().create(std::string(name), inputs);
}

}  // namespace wearscale::dem
