// wearscale version [--json]
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "wearscale/core/thread_waiting.hpp"
#include "wearscale/core/version.hpp"
#include "wearscale/io/library_versions.hpp"

namespace wearscale::app {

Command add_version(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the version of wearscale and of its libraries");
  auto json = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json, "Print as JSON");
  return [json]() {
    if (*json) {
      nlohmann::json libs = nlohmann::json::object();
      for (const auto& [name, v] : library_versions()) libs[name] = v;
      std::cout << nlohmann::json{{"wearscale", version()}, {"libraries", libs}, {"threads_wait", thread_waiting()}}.dump(2)
                << '\n';
      return 0;
    }
    std::cout << "wearscale " << version() << '\n';
    for (const auto& [name, v] : library_versions()) std::cout << fmt::format("  {:<14} {}\n", name, v);
    std::cout << fmt::format("threads wait: {}\n", thread_waiting());
    return 0;
  };
}

}  // namespace wearscale::app
