#pragma once
// A study: the one runnable unit of wearscale. The scale pipeline of a case
// ([scale.*]), a contact, a surface, a wear map, a DEM study, a strength table:
// each declares its keys (the schema) and runs against a RunContext that owns
// its results, files, run.h5, checkpoints and progress. The runner
// (studies/runner.hpp) does everything around a run once for all of them:
// output folder and lock, summary.json, run.h5 provenance, --resume, --set,
// --json and [sweep].
//
// A new study is one file in studies/src/ holding the class and, beside it,
// its registration line:
//
//   WEARSCALE_STUDY(ContactStudy)
//
// The build collects these lines (cmake/WearscaleRegistrations.cmake) into
// study_registry(), so nothing else is edited.
#include <memory>
#include <string>
#include <vector>

#include "wearscale/core/registry.hpp"
#include "wearscale/coupling/run_context.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/core/key_spec.hpp"

namespace wearscale::studies {

using coupling::RunContext;

/// One key of a study (declared in core/key_spec.hpp; the key tables, io/key_table.hpp, produce it).
using KeySpec = wearscale::KeySpec;
using Schema = wearscale::Schema;

/// The key of `schema` named `key` (nullptr if there is none).
const KeySpec* find_key(const Schema& schema, const std::string& key);
/// The schema's keys closest in spelling to `key` (for "did you mean").
std::vector<std::string> closest_keys(const Schema& schema, const std::string& key, std::size_t at_most = 3);
/// The help line of a key: "doc [unit, range, default]: key".
std::string help_line(const KeySpec& spec);
/// The keys of a [materials.define.<name>] table (declared once in
/// io/material_definitions.hpp), as "materials.define.<name>.<key>": for the
/// schemas of the studies that read case-defined materials.
Schema material_schema();
/// A Markdown table of the schema (the key tables of docs/).
std::string markdown_table(const Schema& schema);

class Study {
 public:
  virtual ~Study() = default;
  /// The study's name: "contact", "pipeline", ...
  virtual std::string name() const = 0;
  /// One line: what it computes.
  virtual std::string summary() const = 0;
  /// Its keys.
  virtual Schema schema() const = 0;
  /// The case name and output folder of a case that names neither.
  virtual std::string default_case_name() const { return name(); }
  /// The output folder of a case that names none; empty: out/<case name>.
  virtual std::string default_output_dir() const { return {}; }
  /// Reads and checks every key the study uses before anything is written
  /// (InputError on a bad one), and may record the values it resolved
  /// (defaults included) in `inputs`, so that summary.json's parameters and
  /// run.h5's case hold every value the run used; a study that reads its keys
  /// at the start of run() need not override it. Returns the parts it runs,
  /// in order (the scales of a pipeline), for the summary.
  virtual std::vector<std::string> prepare(Config& /*inputs*/) { return {}; }
  /// The memory prepare() keeps until run() (a topography it read, a grid it
  /// planned), in bytes: a sweep holds every run prepared before the first
  /// starts, and checks their sum against the memory limit first.
  virtual double prepared_bytes() const { return 0.0; }
  /// Computes, writing its outputs into context.output_dir() and reporting its
  /// headline figures and files to `context`. Checks every key before any
  /// work (config.reject_unknown_keys()), when prepare() did not.
  virtual void run(const Config& inputs, RunContext& context) = 0;

  /// Under `mpirun -np P` (P > 1): whether the study spreads its work over
  /// the ranks (the runner refuses the others). Rank 0 calls run(); every
  /// other rank calls run_other_rank(), which makes the same collective calls
  /// and writes nothing. prepare() runs on every rank, so its refusals are the
  /// same on all of them.
  virtual bool distributed() const { return false; }
  virtual void run_other_rank(const Config& /*inputs*/) {}
  /// A distributed run that checkpoints and resumes under mpirun (its state
  /// gathered to rank 0 by collective calls); the others are resumed without.
  virtual bool resumes_distributed() const { return false; }
  /// Whether a run makes MPI calls of its own on the thread that runs it (a
  /// LAMMPS instance): the runs of a sweep under mpirun then go to the ranks'
  /// main threads only (mpi::FarmOptions::root_computes).
  virtual bool calls_mpi() const { return false; }

  /// Whether a run holds ensembles of independent tasks (a rough wear map's
  /// surfaces, nano/dem's junction runs, a strength table's points): those
  /// a shard (--task K/N) splits, and whose finished tasks a resumed run keeps.
  virtual bool has_ensembles() const { return false; }

  /// After prepare(): an estimate of the run's work (see coupling::Scale::
  /// estimated_cost; 0: not known), by which a sweep starts its runs, the
  /// costliest first.
  virtual double estimated_cost() const { return 0.0; }

  /// What a sweep over this study adds besides its table (plots of the
  /// runs' curves), given each run's folder and label; returns the files written.
  struct SweepRuns {
    const Config* probe;              ///< the case with its --set options
    std::string key, series_key;      ///< the swept keys
    bool numeric_values = false;      ///< the swept values are all numbers
    std::vector<std::filesystem::path> folders;
    std::vector<std::string> labels;
    std::vector<std::string> values, series_values;  ///< each run's value of key (and of series_key) as written
    std::vector<std::pair<std::string, std::filesystem::path>> tables;  ///< label, sweep table
    std::vector<std::string> result_names;
    std::string case_name;
    std::filesystem::path output_dir;
  };
  virtual std::vector<std::filesystem::path> finish_sweep(const SweepRuns& /*runs*/) { return {}; }
};

/// What the registry shows of a study (`wearscale studies`, docs/keys.md).
struct StudyInfo {
  std::string name, summary;
  Schema schema;
  /// The message of an unknown study: the known ones, and the closest.
  static std::string unknown(const std::string& kind, const std::string& name, const std::vector<std::string>& kinds,
                             const std::vector<std::string>& known);
};

/// The studies of the build: the one registry template (core/registry.hpp)
/// of studies, each shown by its name, summary and schema.
class StudyRegistry : public NamedRegistry<StudyInfo, Study> {
 public:
  using NamedRegistry::add;
  /// Registers study class S (WEARSCALE_STUDY): its name, summary and schema from an instance.
  template <class S>
  void add() {
    const std::unique_ptr<Study> s = std::make_unique<S>();
    add({s->name(), s->summary(), s->schema()}, [] { return std::unique_ptr<Study>(std::make_unique<S>()); });
  }
};

/// Every study of the build (each registered by its WEARSCALE_STUDY line).
const StudyRegistry& study_registry();

/// The names the runner keeps for itself in a run's output folder (run.h5,
/// summary.json, checkpoint.h5, log.txt, tasks, logs, task-K-of-N.json, the
/// lock): no output a user names may take one of them.
bool is_reserved_output_name(const std::string& name);

/// The file name a key gives for an output of the study in its folder, checked
/// before any work: a plain name (no folder, not hidden, not empty), ending in
/// one of `extensions` (none given: any), not one the runner keeps for itself
/// (is_reserved_output_name). InputError naming the key and what is allowed.
std::string output_file_name(const Config& c, const std::string& key, const std::string& fallback,
                             const std::vector<std::string>& extensions);

/// The study a case runs: [case] study = NAME, else "pipeline" for a case
/// with [scale.*] tables, else the study named by the case's one top-level
/// table (or table.subtable: [dem.junction] → dem/junction) that is a study's name ([contact] → contact).
std::string study_of(const Config& cfg);

}  // namespace wearscale::studies

/// The registration line beside a study's class: the build's list of studies
/// (generated from these lines) calls the function it defines.
#define WEARSCALE_STUDY(Class)                                  \
  namespace wearscale::studies::registered {                    \
  void add_##Class(StudyRegistry& r) { r.add<Class>(); }        \
  }
