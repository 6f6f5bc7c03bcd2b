#pragma once
// The subcommands of `wearscale`. Each adds itself to the parser and returns
// the function that runs it (returning an exit status).
#include <functional>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json_fwd.hpp>

namespace wearscale::app {

using Command = std::function<int()>;

/// Prints headline figures {name: {value, unit, description}}, one a line.
void print_results(const nlohmann::json& results);
/// The command line this process was started with (for lock files and messages).
const std::string& invocation();
void set_invocation(int argc, char** argv);

Command add_run(CLI::App& app);
Command add_backends(CLI::App& app);
Command add_studies(CLI::App& app);
Command add_version(CLI::App& app);
Command add_surface(CLI::App& app);
Command add_contact(CLI::App& app);
Command add_strength_table(CLI::App& app);
Command add_dem(CLI::App& app);
Command add_wearmap(CLI::App& app);
Command add_completion(CLI::App& app);
Command add_merge(CLI::App& app);
Command add_check(CLI::App& app);

}  // namespace wearscale::app
