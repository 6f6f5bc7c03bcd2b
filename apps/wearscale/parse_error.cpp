#include "parse_error.hpp"

#include <algorithm>
#include <cctype>
#include <vector>

#include <fmt/format.h>

#include "wearscale/core/edit_distance.hpp"

namespace wearscale::app {

namespace {
// The command the words went to: the deepest subcommand parsed, and its words ("wearscale dem junction").
std::pair<const CLI::App*, std::string> command_of(const CLI::App& app) {
  const CLI::App* cmd = &app;
  std::string path = "wearscale";
  for (;;) {
    const auto subs = cmd->get_subcommands();
    if (subs.empty()) return {cmd, path};
    cmd = subs.front();
    path += " " + cmd->get_name();
  }
}

// Every option spelling the command takes, its parents' too (-q, -j after the command).
std::vector<std::string> option_names(const CLI::App* cmd) {
  std::vector<std::string> names;
  for (const CLI::App* a = cmd; a != nullptr; a = a->get_parent())
    for (const auto* o : a->get_options()) {
      for (const auto& n : o->get_lnames()) names.push_back("--" + n);
      for (const auto& n : o->get_snames()) names.push_back("-" + n);
    }
  return names;
}

bool is_number(const std::string& word) {
  return word.size() > 1 && (std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.');
}
}  // namespace

std::string parse_error_line(const CLI::App& app, int argc, char** argv, const CLI::ParseError& error) {
  const auto [cmd, path] = command_of(app);
  const auto names = option_names(cmd);
  for (int k = 1; k < argc; ++k) {
    const std::string word = argv[k];
    if (word.size() < 2 || word[0] != '-' || word == "--" || is_number(word)) continue;
    const std::string name = word.substr(0, word.find('='));
    if (std::find(names.begin(), names.end(), name) != names.end()) continue;
    // Short options may be grouped (-qv): each letter is one.
    if (name[1] != '-' && std::all_of(name.begin() + 1, name.end(), [&](char c) {
          return std::find(names.begin(), names.end(), std::string("-") + c) != names.end();
        }))
      continue;
    std::string best;
    std::size_t best_d = std::max<std::size_t>(2, name.size() / 4) + 1;
    for (const auto& n : names)
      if (n.starts_with("--"))
        if (const auto d = edit_distance(n, name); d < best_d) best_d = d, best = n;
    return fmt::format("{}: unknown option '{}'{} (the options: {} --help)", path, name,
                       best.empty() ? "" : fmt::format("; did you mean {}?", best), path);
  }
  return fmt::format("{}: {} (the options: {} --help)", path, error.what(), path);
}

}  // namespace wearscale::app
