#include "runner_shard.hpp"

#include <charconv>
#include <cstdint>
#include <string_view>
#include <system_error>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/sha256.hpp"
#include "wearscale/core/task_store.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/utf8.hpp"
#include "runner_execute.hpp"
#include "runner_output_folder.hpp"

namespace wearscale::studies::runner {

std::optional<Shard> parse_shard(const std::optional<std::string>& given) {
  if (!given) return std::nullopt;
  const std::string& text = *given;
  const auto bad = [&] {
    return InputError(fmt::format("--task '{}': not a shard; allowed: K/N with 1 <= K <= N <= 1000000 (the K-th of N "
                                  "shards of the case's ensemble), e.g. --task 2/8",
                                  is_utf8(text) ? text : std::string("?")));
  };
  const auto slash = text.find('/');
  if (slash == std::string::npos) throw bad();
  const auto number = [&](std::string_view s) {
    std::size_t v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (s.empty() || ec != std::errc() || ptr != s.data() + s.size() || v < 1 || v > 1000000) throw bad();
    return v;
  };
  const std::string_view all(text);
  Shard shard{number(all.substr(0, slash)), number(all.substr(slash + 1))};
  if (shard.index > shard.of) throw bad();
  return shard;
}

std::string manifest_name(const Shard& shard) { return fmt::format("task-{}-of-{}.json", shard.index, shard.of); }

void write_manifest(const std::filesystem::path& dir, const Shard& shard, const std::string& ensemble,
                    const std::string& study, const RunOptions& options, const std::string& command,
                    const nlohmann::json& extra) {
  nlohmann::json manifest = {
      {"ensemble", ensemble},
      {"task", shard.index},
      {"of", shard.of},
      {"study", study},
      {"case_file", options.case_file.string()},
      {"case_file_absolute",
       options.case_file.empty() ? std::string() : std::filesystem::absolute(options.case_file).string()},
      {"case_text", options.case_text ? *options.case_text
                    : options.case_file.empty()
                        ? std::string()
                        : read_text_file(options.case_file, "case file", std::uintmax_t{1} << 26)},
      {"flags", options.flags},
      {"overrides", options.overrides},
      {"command", command}};
  manifest.update(extra);
  write_file_atomically(dir / manifest_name(shard), manifest.dump(2) + "\n", Commit::Now);
}

std::string ensemble_id(const SweepPlan& plan) {
  Sha256 h;
  h.field(case_fingerprint(plan.sweep.parameters));
  h.field(plan.sweep.parameters["sweep"].dump());
  h.field(plan.sweep.study);
  return h.hex();
}

std::string ensemble_id(const PreparedRun& run) {
  Sha256 h;
  h.field(run.fingerprint);
  h.field(run.summary.study);
  return h.hex();
}

RunSummary run_shard(PreparedRun& run, const RunOptions& options, const Shard& shard) {
  if (!run.study->has_ensembles())
    throw InputError(fmt::format("--task {}: study '{}' runs one task, not an ensemble; --task K/N shards the runs "
                                 "of a [sweep], a rough wear map's surfaces, nano/dem's junction runs and a "
                                 "strength table's points (run it without --task)",
                                 shard.text(), run.summary.study));
  const std::string command = command_line(options, thread_budget());
  const std::string ensemble = ensemble_id(run);
  const auto& dir = run.summary.output_dir;
  const OutputLock lock = OutputLock::folder(dir, command, OutputLock::Mode::Shared, ensemble);
  if (options.resume_dir) find_resume_point(run);
  if (run.complete) return run.summary;
  write_manifest(dir, shard, ensemble, run.summary.study, options, command, {{"kind", "run"}});
  run.tasks = mpi::TaskStore::Mode::Shard;
  run.shard = shard.index, run.shards = shard.of;
  FFTPlanCache::global().set_rigor(run.fft_rigor);
  log::info("case '{}': shard {} of its ensembles → {}", run.summary.case_name, shard.text(), dir.string());
  try {
    execute(run, options, true, nullptr);
  } catch (const mpi::ShardDone& e) {
    log::info("shard {} done ({}); once every shard is: wearscale merge {}", shard.text(), e.what(), dir.string());
  } catch (const Interrupted& e) {
    rethrow_interrupted(e, command, dir);
  }
  RunSummary part = run.summary;
  part.results = nlohmann::json::object();
  part.files = {dir / manifest_name(shard)};
  return part;
}

}  // namespace wearscale::studies::runner
