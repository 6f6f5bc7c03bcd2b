// wearscale studies [STUDY] [--json]: every registered study and what it
// computes, or the case keys of one (its schema).
#include <iostream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "completion.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::app {

Command add_studies(CLI::App& app) {
  auto* cmd = app.add_subcommand("studies", "List the registered studies, or the case keys of one");
  auto study = std::make_shared<std::string>();
  auto json = std::make_shared<bool>(false);
  with_choices(cmd->add_option("study", *study, "A study's name: print its case keys"),
               studies::study_registry().names());
  cmd->add_flag("--json", *json, "Print the list (or the keys) as JSON");
  return [study, json]() {
    const auto& registry = studies::study_registry();
    if (!study->empty()) {
      const auto& info = registry.info(*study);  // InputError naming the known studies
      if (*json) {
        nlohmann::json keys = nlohmann::json::array();
        for (const auto& k : info.schema)
          keys.push_back({{"key", k.key}, {"type", k.type}, {"range", k.range}, {"unit", k.unit},
                          {"default", k.fallback}, {"doc", k.doc}, {"flag", k.flag}});
        std::cout << nlohmann::json{{"name", info.name}, {"summary", info.summary}, {"keys", keys}}.dump(2) << '\n';
        return 0;
      }
      std::cout << fmt::format("{}: {}\n", info.name, info.summary);
      for (const auto& k : info.schema) std::cout << "  " << studies::help_line(k) << '\n';
      return 0;
    }
    const auto list = registry.list();
    if (*json) {
      nlohmann::json out = nlohmann::json::array();
      for (const auto& s : list) out.push_back({{"name", s.name}, {"summary", s.summary}});
      std::cout << out.dump(2) << '\n';
      return 0;
    }
    for (const auto& s : list) std::cout << fmt::format("{:<22} {}\n", s.name, s.summary);
    return 0;
  };
}

}  // namespace wearscale::app
