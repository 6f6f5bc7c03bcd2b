#include "wearscale/dem/contact_law.hpp"

#include <algorithm>
#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

namespace registered {
#define WEARSCALE_LAW(key) ContactLawEntry contact_law_##key();
#include "contact_laws.inc"
#undef WEARSCALE_LAW
}  // namespace registered

void ContactLaw::prepare(const Particles&, const NeighborList&) {}

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

std::vector<std::string> contact_law_names() {
  std::vector<std::string> names;
  for (const auto& e : contact_laws()) names.emplace_back(e.name);
  return names;
}

std::unique_ptr<ContactLaw> make_contact_law(std::string_view name, const ContactLawInputs& inputs) {
  for (const auto& e : contact_laws())
    if (name == e.name) return e.make(inputs);
  throw InputError(fmt::format("unknown DEM contact law '{}'; allowed: {}", name, fmt::join(contact_law_names(), ", ")));
}

}  // namespace wearscale::dem
