#include "case_report.hpp"

#include <stdlib.h>

#include <cerrno>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/coupling/run_context.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::studies {

void check_keys_in_run(Study& study, const Config& cfg) {
  std::error_code ec;
  const auto tmp = std::filesystem::temp_directory_path(ec);
  std::string scratch = ((ec ? std::filesystem::path("/tmp") : tmp) / "wearscale-check-XXXXXX").string();
  if (mkdtemp(scratch.data()) == nullptr)
    throw OutputError(fmt::format("cannot make a scratch folder {} to check the keys study '{}' reads in its run: {}",
                                  scratch, study.name(), std::strerror(errno)));
  struct Remove {
    std::filesystem::path dir;
    ~Remove() {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  } remove{scratch};
  struct Stop {
    const Config& cfg;
    ~Stop() { cfg.stop_when_checked(false); }
  } stop{cfg};
  cfg.stop_when_checked(true);
  try {
    H5Writer h5(remove.dir / "run.h5");
    coupling::RunContext context(remove.dir, h5, false, nullptr);
    study.run(cfg, context);
  } catch (const CaseChecked&) {
    return;
  } catch (const OutputError&) {
    throw;
  } catch (const InputError& e) {
    if (cfg.has_collected_errors()) throw cfg.collected_with(e.what());
    throw;
  }
  throw std::logic_error(fmt::format("study '{}' ran without checking the whole case (Config::reject_unknown_keys)",
                                     study.name()));
}

void describe_defaults(CaseReport& report, const Study& study, const Config& cfg) {
  report.parameters = cfg.to_json_with_defaults();
  report.defaults = cfg.applied_defaults();
  report.described_defaults = nlohmann::json::object();
  for (const auto& key : study.schema()) {
    if (key.fallback.empty() || cfg.has(key.key) || report.defaults.contains(key.key)) continue;
    report.described_defaults[key.key] = key.fallback;
  }
}

nlohmann::json CaseReport::to_json() const {
  std::vector<std::string> dirs;
  for (const auto& d : output_dirs) dirs.push_back(d.string());
  nlohmann::json runs_memory = nlohmann::json::array();
  for (const auto& run : memory) {
    nlohmann::json items = nlohmann::json::array();
    double largest = 0.0;
    for (const auto& [what, bytes] : run) {
      items.push_back({{"what", what}, {"bytes", bytes}});
      largest = std::max(largest, bytes);
    }
    runs_memory.push_back(
        {{"bytes", run.empty() ? nlohmann::json(nullptr) : nlohmann::json(largest)}, {"declared", items}});
  }
  nlohmann::json j = {{"valid", true},
                      {"study", study},
                      {"case", case_name},
                      {"case_file", case_file},
                      {"scales", scales},
                      {"output_dirs", dirs},
                      {"parameters", parameters},
                      {"defaults", defaults},
                      {"described_defaults", described_defaults},
                      {"memory", {{"runs", runs_memory},
                                  {"limit_bytes", memory_limit().bytes},
                                  {"limit_source", memory_limit().source}}}};
  if (!sweep_key.empty()) j["sweep"] = {{"key", sweep_key}, {"values", sweep_values}};
  return j;
}

namespace {

std::string toml_key(const std::string& k) {
  const bool bare = !k.empty() && k.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-") ==
                                      std::string::npos;
  return bare ? k : nlohmann::json(k).dump();
}

std::string toml_value(const nlohmann::json& v) {
  if (v.is_string()) {
    const auto& s = v.get_ref<const std::string&>();
    return s == "inf" || s == "-inf" ? s : v.dump();  // an infinite number, as the case's JSON writes it
  }
  if (v.is_array()) {
    std::string out = "[";
    for (std::size_t k = 0; k < v.size(); ++k) out += (k ? ", " : "") + toml_value(v[k]);
    return out + "]";
  }
  if (v.is_object()) {
    std::string out = "{ ";
    bool first = true;
    for (const auto& [k, x] : v.items()) {
      out += (first ? "" : ", ") + toml_key(k) + " = " + toml_value(x);
      first = false;
    }
    return out + " }";
  }
  if (v.is_number_float()) return fmt::format("{}", v.get<double>());
  return v.dump();
}

// One table of the resolved case: its values, then its sub-tables; a value the run
// defaults is marked, and a schema key the run works out is listed commented out.
void write_table(std::string& out, const nlohmann::json& table, const std::string& prefix, const nlohmann::json& defaults,
                 const nlohmann::json& described) {
  std::vector<std::string> lines;
  for (const auto& [k, v] : table.items()) {
    if (v.is_object()) continue;
    const std::string key = prefix.empty() ? k : prefix + "." + k;
    lines.push_back(fmt::format("{} = {}{}", toml_key(k), toml_value(v), defaults.contains(key) ? "    # default" : ""));
  }
  for (const auto& [key, text] : described.items())
    if (key.rfind('.') != std::string::npos && key.substr(0, key.rfind('.')) == prefix)
      lines.push_back(fmt::format("# {} = {}    # default, worked out by the run", key.substr(key.rfind('.') + 1),
                                  text.get<std::string>()));
  if (!lines.empty()) {
    if (!prefix.empty()) out += fmt::format("\n[{}]\n", prefix);
    for (const auto& l : lines) out += l + "\n";
  }
  for (const auto& [k, v] : table.items())
    if (v.is_object()) write_table(out, v, prefix.empty() ? toml_key(k) : prefix + "." + toml_key(k), defaults, described);
}

}  // namespace

std::string CaseReport::text() const {
  std::string out = fmt::format("# case '{}' ({}): valid; study {}{}\n", case_name,
                                case_file.empty() ? "the command's keys" : case_file, study,
                                scales.empty() ? "" : fmt::format(" ({})", fmt::join(scales, " → ")));
  if (sweep_key.empty())
    out += fmt::format("# output folder: {} (nothing written by the check)\n", output_dirs.front().string());
  else
    out += fmt::format("# a sweep of {} runs over {} into {}/... (nothing written by the check)\n", output_dirs.size(),
                       sweep_key, output_dirs.front().parent_path().string());
  // The runs' memory, as each declared it before starting: the largest need (each is a whole
  // data set's, checked against the limit; two may overlap, so they are not summed).
  std::size_t largest = 0;
  double most = -1.0;
  for (std::size_t k = 0; k < memory.size(); ++k)
    for (const auto& m : memory[k])
      if (m.second > most) most = m.second, largest = k;
  const auto& limit = memory_limit();
  if (most < 0.0) {
    out += fmt::format("# memory: study {} declares none before it starts (it sizes its data as the run builds "
                       "them); this process may use {} ({})\n",
                       study, format_bytes(limit.bytes), limit.source);
  } else {
    std::string items;
    for (const auto& [what, bytes] : memory[largest])
      items += fmt::format("\n#   {}: {}", what, format_bytes(bytes));
    out += fmt::format("# memory declared before the run starts{}: {} (the largest need), of the {} this process "
                       "may use ({}):{}\n",
                       memory.size() > 1 ? fmt::format(" (the largest of the {} runs, run {})", memory.size(), largest + 1)
                                         : std::string(),
                       format_bytes(most), format_bytes(limit.bytes), limit.source, items);
  }
  out += "# time: not estimated before the run (a run shows its rate and time left as it goes)\n";
  out += "# the resolved case, every default the run applies marked:\n";
  write_table(out, parameters, "", defaults, described_defaults);
  return out;
}

}  // namespace wearscale::studies
