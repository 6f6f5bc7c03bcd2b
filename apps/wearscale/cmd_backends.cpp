// wearscale backends [--json]: every registered scale backend, what it
// consumes and what it provides.
#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearscale/coupling/scale.hpp"

namespace wearscale::app {

Command add_backends(CLI::App& app) {
  auto* cmd = app.add_subcommand("backends", "List the registered scale backends and the quantities they exchange");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "Print the list as JSON");
  return [json]() {
    const auto list = coupling::scale_registry().list();
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& b : list)
        out.push_back({{"kind", b.kind}, {"name", b.name}, {"summary", b.summary},
                       {"consumes", b.consumes}, {"provides", b.provides}});
      std::cout << out.dump(2) << '\n';
      return 0;
    }
    for (const auto& b : list) {
      std::cout << fmt::format("{:<22} {}\n", b.id(), b.summary);
      std::cout << fmt::format("{:<22}   consumes: {}\n", "", b.consumes.empty() ? "-" : fmt::format("{}", fmt::join(b.consumes, ", ")));
      std::cout << fmt::format("{:<22}   provides: {}\n", "", fmt::join(b.provides, ", "));
    }
    return 0;
  };
}

}  // namespace wearscale::app
