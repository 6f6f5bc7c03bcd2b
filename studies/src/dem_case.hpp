#pragma once
// What the DEM studies (`wearscale dem ...`, one file each: the patch tests of
// §6.2, the sheared junction of §6.3, the sheared rough surfaces of §7.2, the
// loose particles trapped between flat surfaces of §7.3 and the oxidized
// asperity of §9.3.3) share: a study's schema from its key tables ([dem] and
// its own, dem_keys.hpp), and what a run does around its driver (checkpoints,
// progress, snapshots, the force history). Private to the studies.
//
// Each study validates every key before it starts and writes its outputs into
// the run's folder. Each saves its state into the run's checkpoints as it goes
// (owner "dem/<study>", with the position of its snapshot file) and continues
// from the state restored: a killed run resumed gives the same outputs bit for
// bit (one thread).
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "wearscale/core/progress.hpp"
#include "wearscale/dem/cohesive_material.hpp"
#include "wearscale/dem/dump_writer.hpp"
#include "wearscale/dem/run_checkpoints.hpp"
#include "wearscale/dem/sliding_cell.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/studies/study.hpp"
#include "dem_keys.hpp"

namespace wearscale::studies {

// ---- Around a study's run ---------------------------------------------------

/// While one lives on rank 0 of an mpirun job, the LAMMPS engines the study
/// makes span every rank (the others serve them: DemStudy::run_other_rank).
class EngineRanks {
 public:
  explicit EngineRanks(const std::string& engine);
  ~EngineRanks();
  EngineRanks(const EngineRanks&) = delete;
  EngineRanks& operator=(const EngineRanks&) = delete;

 private:
  struct Served;
  std::unique_ptr<Served> served_;
};

/// A study's hooks into the run's checkpoints (owner "dem/<study>"). With a
/// snapshot file, each checkpoint also records how far that file has got, and
/// a resumed study continues it.
dem::RunCheckpoints study_checkpoints(Checkpointer* checkpoints, const std::string& owner, dem::DumpWriter* dump);
/// A progress bar that starts at the resumed step.
std::unique_ptr<Progress> progress_bar(const std::string& name, long planned, const dem::RunCheckpoints& hooks);

/// The OVITO snapshots of a sliding cell every `every` steps (and the first
/// and last), with the worn flag as an extra column, and its progress bar.
struct SlidingDumps {
  dem::DumpWriter writer;
  long every;
  std::unique_ptr<Progress> bar;
  void operator()(const dem::SlidingCell& cell, long step, long planned, const std::string& name,
                  const dem::RunCheckpoints& hooks);
  void write(const dem::SlidingCell& cell);
  long cell_record_every = 1;
};

/// The history of a wear study as CSV (sliding distance and forces in the
/// columns plot_junction_force reads) and as the /history table of `h5`;
/// returns both files' paths.
std::vector<std::string> write_sliding_history(const std::vector<dem::SlidingSample>& history,
                                               const std::filesystem::path& csv, H5Writer& h5,
                                               const std::string& title);

/// The start of every DEM study's run: its own table [dem.<study>]
/// (`section`) read with `table` into `keys`, which hold what [dem] gives
/// them (with_dem for a sliding cell: the pressure's range is the material's),
/// then every key of the case checked unless the study reads more first
/// (`check_every_key` false). Returns the view of [dem.<study>], whose keys
/// the driver's later refusals name.
template <class K>
Config read_study_keys(const Config& root, const std::string& section, const KeyTable<K>& table, K& keys,
                       bool check_every_key = true) {
  const Config c = root.section(section);
  table.read(c, keys);
  if (check_every_key) root.reject_unknown_keys();
  return c;
}

/// What the DEM studies share: case name "dem", folder out/dem-<study>, the
/// schema of their key tables, [dem] read with theirs, the engine's ranks
/// under mpirun, and the outputs their driver lists. A study gives its [dem]
/// table and the rows of its own table [dem.<study>].
class DemStudy : public Study {
 public:
  std::string default_case_name() const override { return "dem"; }
  /// The rows of [dem], then those of [dem.<study>].
  Schema schema() const final;
  /// [dem] engine = "lammps": under mpirun one run over every rank (LAMMPS'
  /// domain decomposition), rank 0 writing the outputs and checkpoints.
  std::vector<std::string> prepare(Config& inputs) override;
  bool distributed() const override { return engine_ == "lammps"; }
  bool resumes_distributed() const override { return engine_ == "lammps"; }
  bool calls_mpi() const override { return engine_ == "lammps"; }
  void run_other_rank(const Config&) override;
  std::string default_output_dir() const override;

 protected:
  /// This study's [dem] table (dem_table with its options).
  virtual const KeyTable<DemKeys>& dem_keys() const = 0;
  /// The rows of the study's own table, named "dem.<study>.<key>".
  virtual Schema study_keys() const = 0;
  /// [dem] read with dem_keys(), and the material it names.
  DemInputs read_dem(const Config& root) const;

  std::string engine_ = "wearscale";
  /// The driver's outputs (files, verdict) into the context; a sheared
  /// study's force history `<history>_history.csv` plotted.
  static void finish(const nlohmann::json& outputs, RunContext& context, const std::string& history);
};

}  // namespace wearscale::studies
