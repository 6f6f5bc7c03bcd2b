#include "runner_plan.hpp"

#include <omp.h>

#include <algorithm>
#include <exception>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/utf8.hpp"
#include "wearscale/studies/runner_keys.hpp"

namespace wearscale::studies::runner {

Config load(const CaseLoader& parse, const RunOptions& options,
            const std::vector<std::pair<std::string, std::string>>& extra) {
  Config cfg = parse();
  for (const auto& [assignment, flag] : options.flags) cfg.override_value(assignment, flag);
  for (const auto& o : options.overrides) cfg.override_value(o, is_utf8(o) ? "--set " + o : std::string("--set"));
  for (const auto& [value, origin] : extra) cfg.override_value(value, origin);
  return cfg;
}

int thread_budget() { return std::max(1, omp_get_max_threads()); }

std::string command_line(const RunOptions& options, int threads) {
  if (!options.command.empty())  // a command's own line, with its threads
    return options.command.find(" -j") != std::string::npos || options.command.find("--threads") != std::string::npos
               ? options.command
               : options.command + fmt::format(" -j {}", threads);
  std::string line = "wearscale run " + options.case_file.string();
  for (const auto& o : options.overrides) line += fmt::format(" --set '{}'", o);
  return line + fmt::format(" -j {}", threads);
}

std::unique_ptr<Study> study_for(const Config& cfg, const RunOptions& options) {
  cfg.mark_used("case.study");
  return study_registry().create(options.study.empty() ? study_of(cfg) : options.study);
}

namespace {

// A folder given on the command line: a name (not empty, which would be taken as no --out at all) of a
// folder, not "-" (wearscale writes files into a folder, never to stdout).
void require_folder_name(const std::filesystem::path& dir, const char* option) {
  if (dir.empty())
    throw InputError(fmt::format("{} '': an empty folder name; allowed: the name of a folder to write into (without "
                                 "{}: the case's [output] dir)",
                                 option, option));
  if (dir == "-")
    throw InputError(fmt::format("{} -: wearscale writes a folder of files, not to standard output; allowed: the name "
                                 "of a folder (--json prints the results on standard output)",
                                 option));
}

// An output folder given as an existing file is bad input (exit 2), found before anything is written.
void require_folder_or_nothing(const std::filesystem::path& dir, const char* option) {
  std::error_code ec;
  if (std::filesystem::exists(dir, ec) && !std::filesystem::is_directory(dir, ec))
    throw InputError(fmt::format("{} = '{}' cannot be used as an output folder (not a folder); allowed: a folder that "
                                 "can be created and written",
                                 option, dir.string()));
}

// Every key of the case read and checked, stopping at the first error.
PreparedRun prepare_keys(Config cfg_in, const std::optional<std::filesystem::path>& out, const RunOptions& options) {
  PreparedRun run{std::move(cfg_in), {}, {}, {}, PlanRigor::Measure, {}, std::nullopt, false, false,
                  mpi::TaskStore::Mode::Keep, 1, 1, {}, {}};
  Config& cfg = run.cfg;
  run.study = study_for(cfg, options);
  run.summary.study = run.study->name();
  CaseKeys names;
  names.default_name = run.study->default_case_name();  // empty: the case must name itself
  names.default_dir = run.study->default_output_dir();
  case_keys().read(cfg, names);
  run.summary.case_name = names.name;
  run.summary.output_dir = out ? *out : std::filesystem::path(names.output_dir);
  require_folder_or_nothing(run.summary.output_dir, out ? "--out" : "output.dir");
  cfg.mark_used("sweep");  // read by run_case
  // [run]: how the run is carried out, not what it computes.
  RunKeys how;
  run_keys().read(cfg.section("run"), how);
  run.policy = how.checkpoints;
  run.fft_rigor = how.fft_planning;
  // From here on: a plan made while preparing (a generated surface's) would
  // otherwise be measured, and a measured plan picks its algorithm by timing.
  FFTPlanCache::global().set_rigor(run.fft_rigor);
  run.summary.scales = run.study->prepare(cfg);
  run.summary.parameters = cfg.to_json();
  run.fingerprint = case_fingerprint(run.summary.parameters);
  return run;
}

}  // namespace

void require_utf8_paths(const RunOptions& options) {
  require_utf8_path(options.case_file, "case file");
  if (options.output_dir) require_folder_name(*options.output_dir, "--out");
  if (options.resume_dir) require_folder_name(*options.resume_dir, "--resume");
  if (options.output_dir) require_utf8_path(*options.output_dir, "--out");
  if (options.resume_dir) require_utf8_path(*options.resume_dir, "--resume");
}

nlohmann::json provenance_of(const RunSummary& summary, const RunOptions& options) {
  return {{"wearscale_version", WEARSCALE_VERSION}, {"study", summary.study}, {"case_file", options.case_file.string()}};
}

PreparedRun prepare(Config cfg_in, const std::optional<std::filesystem::path>& out, const RunOptions& options) {
  const Config cfg = cfg_in;  // shares the case's state: its errors
  cfg.collect_errors(true);
  const MemoryTally tally;
  PreparedRun run = [&] {
    try {
      return prepare_keys(std::move(cfg_in), out, options);
    } catch (const OutputError&) {
      throw;
    } catch (const InputError& e) {
      if (cfg.has_collected_errors()) throw cfg.collected_with(e.what());
      throw;
    } catch (const std::exception&) {  // a consequence of a value in error standing in: the errors are the news
      if (cfg.has_collected_errors()) cfg.raise_collected_errors();
      throw;
    }
  }();
  cfg.raise_collected_errors();
  cfg.collect_errors(!cfg.fully_checked());
  run.memory = tally.requests();
  return run;
}

}  // namespace wearscale::studies::runner
