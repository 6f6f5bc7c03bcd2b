#pragma once
// A shard of an ensemble (`--task K/N`, a job array): the K-th of N shares of
// a sweep's runs, or of the tasks of one run's ensembles, run into the
// ensemble's folder beside the other shards (a shared folder lock, no shared
// file written); each leaves its manifest, task-K-of-N.json, from which
// merge_shards() writes what a whole run writes. Private to the runner.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "runner_plan.hpp"
#include "runner_sweep_plan.hpp"

namespace wearscale::studies::runner {

/// A shard of an ensemble (--task K/N): the runs k with k mod N = K − 1.
struct Shard {
  std::size_t index = 1, of = 1;  ///< K, N
  std::string text() const { return fmt::format("{}/{}", index, of); }
  bool owns(std::size_t k) const { return k % of == index - 1; }
};

/// The shard --task gives ("K/N"; none: the whole ensemble); InputError for anything else.
std::optional<Shard> parse_shard(const std::optional<std::string>& given);

/// task-K-of-N.json
std::string manifest_name(const Shard& shard);

/// A shard's manifest in the ensemble's folder: which ensemble, which shard,
/// and the case as it ran (the file, its text, the flags), for `merge`;
/// `extra` adds what the kind of ensemble needs (a sweep's runs, "kind": "run").
void write_manifest(const std::filesystem::path& dir, const Shard& shard, const std::string& ensemble,
                    const std::string& study, const RunOptions& options, const std::string& command,
                    const nlohmann::json& extra);

/// The id shared by the shards of one sweep: the case that determines the
/// results, with its sweep (not [run] or [output]: a resume may change those).
std::string ensemble_id(const SweepPlan& plan);
/// The id shared by the shards of one run's ensembles: its study and the case that determines the results.
std::string ensemble_id(const PreparedRun& run);

/// One shard of a run's ensembles (--task K/N, no mpirun): its share of every
/// ensemble the run meets, kept in tasks/ beside the other shards'; it stops
/// at the first ensemble that lacks theirs (exit 0), writing none of the
/// run's outputs (merge does).
RunSummary run_shard(PreparedRun& run, const RunOptions& options, const Shard& shard);

}  // namespace wearscale::studies::runner
