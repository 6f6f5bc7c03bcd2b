#include "runner_output_folder.hpp"

#include <algorithm>
#include <cstdint>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/log.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/task_store.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "result_bounds.hpp"

namespace wearscale::studies::runner {

namespace {

// A completed run's summary.json is a sweep's (it has "sweep") or a single run's: --resume continues one
// of the same kind only (a sweep resumed over a single run's folder would replace its outputs).
void require_summary_of_kind(const std::filesystem::path& summary_file, const nlohmann::json& j, bool sweep) {
  const bool is_sweep = j.is_object() && j.contains("sweep");
  if (is_sweep == sweep) return;
  throw InputError(fmt::format("--resume: {} is the summary of a completed {}, and the case is {}; resume it with the "
                               "case it was run with, or write to another folder (nothing was changed)",
                               summary_file.string(), is_sweep ? "sweep" : "single run (no [sweep])",
                               sweep ? "a sweep" : "a single run"));
}

// Subfolders of `dir` (one or two levels down) that hold a run: its summary.json, checkpoint.h5 or log.txt
// (with `sweep_runs_only`, log.txt alone: the runs of an ensemble).
std::vector<std::filesystem::path> run_folders_in(const std::filesystem::path& dir, bool sweep_runs_only) {
  std::vector<std::filesystem::path> found;
  const auto holds_run = [&](const std::filesystem::path& d) {
    std::error_code ec;
    if (std::filesystem::exists(d / "log.txt", ec)) return true;
    return !sweep_runs_only &&
           (std::filesystem::exists(d / "summary.json", ec) || std::filesystem::exists(d / "checkpoint.h5", ec));
  };
  std::error_code ec;
  for (std::filesystem::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    if (!it->is_directory(ec) || it->path().filename().string().starts_with(".")) continue;
    const auto name = it->path().filename();
    if (name == "tasks" || name == "logs") continue;  // a run's own kept tasks and task logs
    if (holds_run(it->path())) {
      found.push_back(name);
      continue;
    }
    std::error_code inner;
    for (std::filesystem::directory_iterator jt(it->path(), inner), jend; !inner && jt != jend; jt.increment(inner))
      if (jt->is_directory(inner) && holds_run(jt->path())) found.push_back(name / jt->path().filename());
  }
  std::sort(found.begin(), found.end());
  return found;
}

}  // namespace

void refuse_foreign_runs(const std::filesystem::path& dir, const std::vector<std::filesystem::path>& own,
                         bool sweep_runs_only) {
  nlohmann::json previous = nlohmann::json::object();
  std::error_code ec;
  if (std::filesystem::is_regular_file(dir / "summary.json", ec)) try {
      previous = nlohmann::json::parse(read_text_file(dir / "summary.json", "summary", std::uintmax_t{1} << 26));
    } catch (const std::exception&) {
    }
  const auto owned = OutputSet::owned_folders(previous);
  std::vector<std::string> foreign;
  for (const auto& f : run_folders_in(dir, sweep_runs_only)) {
    const auto in = [&](const std::vector<std::filesystem::path>& set) {
      return std::any_of(set.begin(), set.end(), [&](const auto& o) { return o == f || *f.begin() == o; });
    };
    if (!in(own) && !in(owned)) foreign.push_back((dir / f).string());
  }
  if (foreign.empty()) return;
  const std::size_t shown = std::min<std::size_t>(foreign.size(), 3);
  throw OutputError(fmt::format(
      "{} holds {} run folder(s) that are not this run's and that no completed run of the folder lists ({}{}): a "
      "run would leave them mixed with its own; --resume them with the case that made them, move or delete them, or "
      "write to another folder (nothing was changed)",
      dir.string(), foreign.size(), fmt::join(foreign.begin(), foreign.begin() + static_cast<long>(shown), ", "),
      foreign.size() > shown ? ", ..." : ""));
}

void find_resume_point(PreparedRun& run) {
  const auto dir = run.summary.output_dir;
  run.checkpoints.emplace(dir / "checkpoint.h5", run.fingerprint, run.policy);
  std::error_code ec;
  if (std::filesystem::exists(dir / "checkpoint.h5", ec)) {
    run.checkpoints->load();
    run.resume = true;
    return;
  }
  const auto summary_file = dir / "summary.json";
  if (!std::filesystem::exists(summary_file, ec)) {
    log::info("{}: no checkpoint yet: the run starts from the beginning", dir.string());
    return;
  }
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(summary_file, "summary", std::uintmax_t{1} << 26));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a wearscale summary ({})", summary_file.string(), e.what()));
  }
  if (!j.is_object()) throw InputError(fmt::format("{}: not a wearscale summary", summary_file.string()));
  require_summary_of_kind(summary_file, j, false);
  const std::string was = case_fingerprint(j.value("parameters", nlohmann::json::object()));
  if (was != run.fingerprint) {
    const std::string diff = describe_case_difference(was, run.fingerprint);
    throw InputError(fmt::format("{}: this run completed with other parameters{}; resume with the case file and --set "
                                 "options it was run with, or write to another folder",
                                 summary_file.string(), diff.empty() ? "" : " (" + diff + ")"));
  }
  if (const std::string broken = OutputSet::verify(dir, j); !broken.empty()) {
    log::warn("{}: the outputs of the completed run are not intact ({}): the run starts again", dir.string(), broken);
    return;
  }
  // Its figures as a computed run's are held to: a summary changed by hand (or by another program) is no result.
  if (const std::string why = results_problem(j.value("results", nlohmann::json::object())); !why.empty())
    throw InputError(fmt::format("{}: {}; no run writes that (the summary was changed or damaged): delete {} and run "
                                 "it again",
                                 summary_file.string(), why, dir.string()));
  run.summary.results = j.value("results", nlohmann::json::object());
  for (const auto& [key, value] : j.items())  // the study's own fields
    if (!RunSummary{}.to_json().contains(key) && key != "results") run.summary.notes[key] = value;
  for (const auto& f : j.value("files", nlohmann::json::array()))
    if (f.is_string()) run.summary.files.emplace_back(f.get<std::string>());
  run.complete = true;
  run.summary.complete_before = true;
}

void check_fresh_start(const PreparedRun& run) {
  require_fresh_start(run.summary.output_dir / "checkpoint.h5");
  if (mpi::TaskStore::holds_tasks(tasks_dir(run)))
    throw OutputError(fmt::format("{} holds the finished tasks of an unfinished run; continue it with --resume {}, or "
                                  "delete {} to start afresh",
                                  run.summary.output_dir.string(), run.summary.output_dir.string(),
                                  tasks_dir(run).string()));
}

void require_sweep_summary_or_none(const std::filesystem::path& dir) {
  const auto file = dir / "summary.json";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec)) return;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(file, "summary", std::uintmax_t{1} << 26));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not a wearscale summary ({})", file.string(), e.what()));
  }
  require_summary_of_kind(file, j, true);
}

void claim_task_store(const PreparedRun& run) {
  std::error_code ec;
  if (!std::filesystem::exists(tasks_dir(run), ec)) return;
  if (!std::filesystem::is_directory(tasks_dir(run), ec))
    throw OutputError(fmt::format("{} is not a folder; a run keeps its finished tasks there: move it away, or write "
                                  "to another folder",
                                  tasks_dir(run).string()));
  const std::string was = mpi::TaskStore::case_of(tasks_dir(run));
  if (was == run.fingerprint) return;
  if (mpi::TaskStore::holds_tasks(tasks_dir(run)))
    log::warn("{}: its kept tasks belong to other parameters; they are run again", tasks_dir(run).string());
  std::filesystem::remove_all(tasks_dir(run), ec);
}

[[noreturn]] void rethrow_interrupted(const Interrupted& e, const std::string& command,
                                      const std::filesystem::path& dir) {
  std::error_code ec;
  bool kept = false;  // anything but the folder's lock: a checkpoint, kept tasks, finished runs
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    kept = kept || entry.path().filename() != OutputLock::kFolderLockName;
  if (!kept) throw Interrupted(fmt::format("{}; nothing was written (run it again to start afresh)", e.what()));
  // A resumed run's own line says it already (as `--resume DIR` or `--resume=DIR`).
  const bool resuming = command.find(" --resume") != std::string::npos;
  throw Interrupted(fmt::format("{}; continue with: {}{}", e.what(), command,
                                resuming ? std::string() : " --resume " + dir.string()));
}

}  // namespace wearscale::studies::runner
