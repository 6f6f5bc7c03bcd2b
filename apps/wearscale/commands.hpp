#pragma once
// The subcommands of `wearscale`. Each adds itself to the parser and returns
// the function that runs it (returning an exit status).
#include <functional>

#include <CLI/CLI.hpp>
#include <nlohmann/json_fwd.hpp>

namespace wearscale::app {

using Command = std::function<int()>;

/// Prints headline figures {name: {value, unit, description}}, one a line.
void print_results(const nlohmann::json& results);

Command add_run(CLI::App& app);
Command add_backends(CLI::App& app);
Command add_version(CLI::App& app);
Command add_surface(CLI::App& app);
Command add_contact(CLI::App& app);
Command add_strength_table(CLI::App& app);
Command add_dem(CLI::App& app);
Command add_wearmap(CLI::App& app);
/// `wearmap rough` (ch. 5), added under the `wearmap` command by add_wearmap.
Command add_wearmap_rough(CLI::App& wearmap);

}  // namespace wearscale::app
