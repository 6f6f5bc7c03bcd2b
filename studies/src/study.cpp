#include "wearscale/studies/study.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/edit_distance.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/io/material_definitions.hpp"

namespace wearscale::studies {

const KeySpec* find_key(const Schema& schema, const std::string& key) {
  for (const auto& k : schema)
    if (k.key == key) return &k;
  return nullptr;
}

std::vector<std::string> closest_keys(const Schema& schema, const std::string& key, std::size_t at_most) {
  std::vector<std::pair<std::size_t, std::string>> scored;
  for (const auto& k : schema) scored.emplace_back(edit_distance(k.key, key), k.key);
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (const auto& [d, k] : scored)
    if (out.size() < at_most && d <= std::max<std::size_t>(2, key.size() / 4)) out.push_back(k);
  return out;
}

std::string help_line(const KeySpec& s) {
  std::vector<std::string> facts;
  if (!s.unit.empty() && s.unit != "1") facts.push_back(s.unit);
  if (!s.range.empty()) facts.push_back(s.range);
  if (!s.fallback.empty()) facts.push_back("default " + s.fallback);
  return fmt::format("{}{}: {}", s.doc, facts.empty() ? "" : fmt::format(" [{}]", fmt::join(facts, "; ")), s.key);
}

Schema material_schema() {
  Schema out;
  for (const auto& k : material_keys()) {
    std::string range = k.allowed;
    if (range.empty() && (k.type == "number" || k.type == "list")) range = k.range.describe();
    out.push_back({"materials.define.<name>." + k.key, k.type, range, k.unit, k.fallback, k.doc, ""});
  }
  return out;
}

std::string markdown_table(const Schema& schema) {
  // A '|' inside a cell ("hcp | amorphous") would end it.
  const auto cell = [](std::string text) {
    for (std::size_t at = text.find('|'); at != std::string::npos; at = text.find('|', at + 2)) text.insert(at, "\\");
    return text;
  };
  std::string out = "| key | type | unit | allowed | default | flag | meaning |\n|---|---|---|---|---|---|---|\n";
  for (const auto& k : schema)
    out += fmt::format("| `{}` | {} | {} | {} | {} | {} | {} |\n", k.key, k.type, k.unit, cell(k.range),
                       k.fallback.empty() ? "" : "`" + cell(k.fallback) + "`", k.flag.empty() ? "" : "`" + k.flag + "`",
                       cell(k.doc));
  return out;
}

bool is_reserved_output_name(const std::string& name) {
  for (const char* kept : {"run.h5", "summary.json", "checkpoint.h5", "log.txt", "tasks", "logs", ".wearscale.lock"})
    if (name == kept) return true;
  // A shard's manifest: task-K-of-N.json.
  return name.starts_with("task-") && name.ends_with(".json") && name.find("-of-") != std::string::npos;
}

std::string output_file_name(const Config& c, const std::string& key, const std::string& fallback,
                             const std::vector<std::string>& extensions) {
  const std::string name = c.string_or(key, fallback);
  const std::filesystem::path path(name);
  const bool plain = !name.empty() && name.front() != '.' && path.filename() == path &&
                     name.find('\0') == std::string::npos;
  const bool extension_ok = extensions.empty() || std::find(extensions.begin(), extensions.end(),
                                                            path.extension().string()) != extensions.end();
  const std::string allowed = fmt::format(
      "a plain file name in the output folder{}{} (run.h5, summary.json, checkpoint.h5, log.txt and task-K-of-N.json "
      "are the runner's own)",
      extensions.empty() ? "" : " ending in ", fmt::join(extensions, " or "));
  if (!plain || !extension_ok) throw c.error(key, "not a file name for an output of the study", allowed);
  if (is_reserved_output_name(name))
    throw c.error(key, fmt::format("'{}' is a name the runner writes itself in every output folder", name), allowed);
  return name;
}

std::string StudyInfo::unknown(const std::string&, const std::string& name, const std::vector<std::string>&,
                               const std::vector<std::string>& known) {
  const std::string best = closest_name(known, name);
  return fmt::format("unknown study '{}'; known studies: {}{}", name, fmt::join(known, ", "),
                     best.empty() ? "" : fmt::format(" (did you mean '{}'?)", best));
}

std::string study_of(const Config& cfg) {
  const auto& registry = study_registry();
  if (cfg.has("case.study")) {
    const std::string name = cfg.string("case.study");
    if (!registry.contains(name)) {
      try {
        registry.create(name);
      } catch (const InputError& e) {
        throw cfg.error("case.study", e.what());
      }
    }
    return name;
  }
  if (cfg.has("scale")) return "pipeline";
  for (const auto& table : cfg.keys()) {
    if (table == "case" || table == "output" || table == "run" || table == "sweep" || table == "materials") continue;
    if (registry.contains(table)) return table;
    for (const auto& sub : cfg.keys(table))
      if (registry.contains(table + "/" + sub)) return table + "/" + sub;
  }
  return "pipeline";  // its checks name what is missing ([scale.<kind>])
}

}  // namespace wearscale::studies
