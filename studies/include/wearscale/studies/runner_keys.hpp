#pragma once
// The keys the runner reads in every case, whatever its study: [case] (its
// name), [output] (its folder), [run] (how the run is carried out: checkpoints,
// FFT planning, what rank 0 gathers) and [sweep] (the values of a key to run the case over). Each is
// declared once in a key table beside the struct it fills; the runner reads
// them through these tables and docs/keys.md lists them.
#include <cstddef>
#include <string>
#include <vector>

#include "wearscale/core/fft.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/key_table.hpp"

namespace wearscale::studies {

/// [case] and [output].
struct CaseKeys {
  std::string name;
  std::string study;
  std::string description;
  std::string output_dir;
  // Not keys: the study's defaults (an empty name: the case must name itself).
  std::string default_name, default_dir;
};
const KeyTable<CaseKeys>& case_keys();

/// [run]: how the run is carried out, not what it computes.
struct RunKeys {
  CheckpointPolicy checkpoints;
  PlanRigor fft_planning = PlanRigor::Measure;
  /// Under mpirun, grids above this many points are not gathered on rank 0
  /// (88 B a point there for the fields and micro-contacts): every rank writes its rows.
  std::size_t gather_limit = std::size_t{4096} * 4096;
};
const KeyTable<RunKeys>& run_keys();

/// [sweep]: the case run once per value of `key` (and once more per value of
/// [sweep.series] key).
struct SweepKeys {
  std::string key;
  std::vector<std::string> values;
  std::string table = "sweep.csv";
  bool parallel = true;
  std::string series_key;
  std::vector<std::string> series_values;
};
const KeyTable<SweepKeys>& sweep_keys();

/// The rows of all of them, with their full names ("case.name", "run.checkpoint_interval").
Schema runner_schema();

}  // namespace wearscale::studies
