// `wearscale merge DIR`: what the shards of an ensemble (--task K/N) left in
// DIR made into the outputs a whole run writes, none of its tasks computed
// again; refused, naming what is missing and which shard owes it, until every
// task is there.
#include <algorithm>
#include <cstdint>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/task_store.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/utf8.hpp"
#include "wearscale/studies/runner.hpp"
#include "runner_execute.hpp"
#include "runner_output_folder.hpp"
#include "runner_plan.hpp"
#include "runner_publish.hpp"
#include "runner_shard.hpp"
#include "runner_sweep_plan.hpp"

namespace wearscale::studies {
namespace runner {
namespace {

// Who owes task k of an ensemble, for merge's refusal: under every shard count the manifests show.
std::string owner_of(std::size_t k, const std::vector<nlohmann::json>& manifests) {
  std::vector<std::size_t> counts;
  for (const auto& m : manifests) {
    const auto of = m["of"].get<std::size_t>();
    if (std::find(counts.begin(), counts.end(), of) == counts.end()) counts.push_back(of);
  }
  std::vector<std::string> owed;
  for (const auto of : counts) {
    const Shard s{k % of + 1, of};
    const bool ran = std::any_of(manifests.begin(), manifests.end(), [&](const auto& m) {
      return m["of"].template get<std::size_t>() == of && m["task"].template get<std::size_t>() == s.index;
    });
    owed.push_back(fmt::format("shard {} {}", s.text(), ran ? "did not finish it" : "has not run"));
  }
  return fmt::format("{}", fmt::join(owed, ", "));
}

// The manifests the shards left in `dir` (task-K-of-N.json), by shard count
// and shard; InputError when there is none, one is not a manifest, or two
// are of different ensembles.
std::vector<nlohmann::json> shard_manifests(const std::filesystem::path& dir) {
  std::error_code ec;
  std::vector<nlohmann::json> manifests;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    if (!name.starts_with("task-") || !name.ends_with(".json") || name.find("-of-") == std::string::npos) continue;
    try {
      manifests.push_back(nlohmann::json::parse(read_text_file(entry.path(), "shard manifest", std::uintmax_t{1} << 26)));
      const auto& m = manifests.back();
      (void)m.at("ensemble").get<std::string>(), (void)m.at("task").get<std::size_t>(), (void)m.at("of").get<std::size_t>();
    } catch (const nlohmann::json::exception& e) {
      throw InputError(fmt::format("{}: not a shard manifest of wearscale ({})", entry.path().string(), e.what()));
    }
  }
  if (manifests.empty())
    throw InputError(fmt::format("merge {}: no shard has run into this folder (no task-K-of-N.json); allowed: the "
                                 "output folder of an ensemble's shards (wearscale run CASE --task K/N --out DIR)",
                                 dir.string()));
  std::sort(manifests.begin(), manifests.end(), [](const auto& a, const auto& b) {
    return std::pair(a["of"].template get<std::size_t>(), a["task"].template get<std::size_t>()) <
           std::pair(b["of"].template get<std::size_t>(), b["task"].template get<std::size_t>());
  });
  const nlohmann::json& first = manifests.front();
  for (const auto& m : manifests)
    if (m["ensemble"] != first["ensemble"])
      throw InputError(fmt::format("merge {}: shards {}/{} and {}/{} ran different cases (ensemble ids differ); a "
                                   "folder holds the shards of one ensemble",
                                   dir.string(), first["task"].get<std::size_t>(), first["of"].get<std::size_t>(),
                                   m["task"].get<std::size_t>(), m["of"].get<std::size_t>()));
  return manifests;
}

// merge of one run's shards: the run once more, every task of its ensembles
// taken from what the shards kept (none computed), its outputs written as an
// unsharded run writes them; refused, naming them, while tasks are missing.
RunSummary merge_run(const std::filesystem::path& dir, Config probe, const RunOptions& options,
                     const std::vector<nlohmann::json>& manifests) {
  if (probe.has("sweep"))
    throw InputError(fmt::format("merge {}: the shards ran one case without a [sweep], which has one now", dir.string()));
  PreparedRun run = prepare(std::move(probe), dir, options);
  if (ensemble_id(run) != manifests.front()["ensemble"].get<std::string>())
    throw InputError(fmt::format("merge {}: the case ({}) is not the one the shards ran (it changed since); merge "
                                 "with the case they ran, or run the ensemble again",
                                 dir.string(), options.case_file.empty() ? "the command's keys" : options.case_file.string()));
  const OutputLock lock = OutputLock::folder(dir, options.command);  // refused while a shard still runs
  find_resume_point(run);
  if (run.complete) {
    log::info("merge {}: the run is already complete", dir.string());
    return run.summary;
  }
  run.tasks = mpi::TaskStore::Mode::Assemble;
  run.owner = [&](std::size_t k) { return owner_of(k, manifests); };
  FFTPlanCache::global().set_rigor(run.fft_rigor);
  try {
    execute(run, options, true, nullptr);
  } catch (const OutputError&) {
    throw;
  } catch (const InputError& e) {
    throw InputError(fmt::format("merge {}: {}; run what is left (the shards named, or all of it with --resume {}), "
                                 "then merge again",
                                 dir.string(), e.what(), dir.string()));
  }
  log::info("merged the tasks of {} shard(s) into {}", manifests.size(), dir.string());
  return run.summary;
}

}  // namespace
}  // namespace runner

using namespace runner;

RunSummary merge_shards(const std::filesystem::path& dir, const std::string& command) {
  require_utf8_path(dir, "merge");
  std::error_code ec;
  if (!std::filesystem::is_directory(dir, ec))
    throw InputError(fmt::format("merge {}: not a folder; allowed: the output folder of an ensemble's shards "
                                 "(wearscale run CASE --task K/N --out DIR)",
                                 dir.string()));
  const std::vector<nlohmann::json> manifests = shard_manifests(dir);
  const nlohmann::json& first = manifests.front();
  // The case as the shards ran it: the case file if it is still where it was, else the text they recorded.
  RunOptions options;
  options.study = first.value("study", "");
  options.case_file = first.value("case_file", "");
  options.flags = first.value("flags", std::vector<std::pair<std::string, std::string>>{});
  options.overrides = first.value("overrides", std::vector<std::string>{});
  options.output_dir = dir;
  options.command = command;
  const std::filesystem::path absolute = first.value("case_file_absolute", "");
  const std::string text = first.value("case_text", "");
  const CaseLoader parse = [&] {
    if (!options.case_file.empty() && std::filesystem::exists(options.case_file)) return Config::load(options.case_file);
    if (!absolute.empty() && std::filesystem::exists(absolute)) return Config::load(absolute);
    return Config::from_string(text, options.case_file.empty() ? "<command line>" : options.case_file.string());
  };
  Config probe = load(parse, options);
  if (first.value("kind", "sweep") == "run") return merge_run(dir, std::move(probe), options, manifests);
  if (!probe.has("sweep"))
    throw InputError(fmt::format("merge {}: the shards' case has no [sweep] any more", dir.string()));
  SweepPlan plan = plan_sweep(parse, options, probe);
  describe_sweep(plan, options);
  if (ensemble_id(plan) != first["ensemble"].get<std::string>())
    throw InputError(fmt::format("merge {}: the case ({}) is not the one the shards ran (it changed since); merge "
                                 "with the case they ran, or run the ensemble again",
                                 dir.string(), options.case_file.empty() ? "the command's keys" : options.case_file.string()));
  const OutputLock lock = OutputLock::folder(dir, command);  // refused while a shard still runs
  std::vector<std::string> missing;
  for (std::size_t k = 0; k < plan.runs.size(); ++k) {
    find_resume_point(plan.runs[k]);
    if (plan.runs[k].complete) continue;
    missing.push_back(fmt::format("task {} ({}: {})", k + 1, plan.runs[k].summary.output_dir.filename().string(),
                                  owner_of(k, manifests)));
  }
  if (!missing.empty())
    throw InputError(fmt::format("merge {}: {} of {} tasks are not complete: {}; run what is left (any shard count) "
                                 "with --resume {}, then merge again",
                                 dir.string(), missing.size(), plan.runs.size(), fmt::join(missing, "; "), dir.string()));
  publish_sweep(plan, probe, std::vector<std::string>(plan.runs.size()));
  log::info("merged {} runs of {} shard(s) into {}", plan.runs.size(), manifests.size(), dir.string());
  return plan.sweep;
}

}  // namespace wearscale::studies
