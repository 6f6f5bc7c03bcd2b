// wearscale backends [--keys] [--json]: every registered scale backend, what
// it consumes and what it provides, and with --keys the keys of its
// [scale.<kind>] table as its key table declares them.
#include <iostream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearscale/coupling/backend_keys.hpp"
#include "wearscale/coupling/scale.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::app {

Command add_backends(CLI::App& app) {
  auto* cmd = app.add_subcommand("backends", "List the registered scale backends and the quantities they exchange");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "Print the list as JSON");
  auto keys = std::make_shared<bool>(false);
  cmd->add_flag("--keys", *keys, "Also list each backend's keys (type, unit, range, default, meaning)");
  return [json, keys]() {
    const auto list = coupling::scale_registry().list();
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& b : list) {
        out.push_back({{"kind", b.kind}, {"name", b.name}, {"summary", b.summary},
                       {"consumes", b.consumes}, {"provides", b.provides}});
        if (*keys) {
          nlohmann::json rows = nlohmann::json::array();
          for (const auto& k : coupling::backend_schema(b.kind, b.name))
            rows.push_back({{"key", k.key}, {"type", k.type}, {"unit", k.unit}, {"allowed", k.range},
                            {"default", k.fallback}, {"meaning", k.doc}});
          out.back()["keys"] = rows;
        }
      }
      std::cout << out.dump(2) << '\n';
      return 0;
    }
    for (const auto& b : list) {
      std::cout << fmt::format("{:<22} {}\n", b.id(), b.summary);
      std::cout << fmt::format("{:<22}   consumes: {}\n", "", b.consumes.empty() ? "-" : fmt::format("{}", fmt::join(b.consumes, ", ")));
      std::cout << fmt::format("{:<22}   provides: {}\n", "", fmt::join(b.provides, ", "));
      if (*keys)
        for (const auto& k : coupling::backend_schema(b.kind, b.name))
          std::cout << fmt::format("{:<22}   {}\n", "", studies::help_line(k));
    }
    return 0;
  };
}

}  // namespace wearscale::app
