#pragma once
// What the DEM studies (`wearscale dem ...`, one file each: the patch tests of
// §6.2, the sheared junction of §6.3, the sheared rough surfaces of §7.2, the
// loose particles trapped between flat surfaces of §7.3 and the oxidized
// asperity of §9.3.3) share, configured by the [dem] table of a case: the
// readers of [dem] (material, contact law, engine); the keys several studies
// name alike, each read by one function beside its schema row so that its
// default, range and unit are written once; the sliding cell of the wear
// studies; and what a run does around its driver (checkpoints, progress,
// snapshots, the force history). Private to the studies.
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

namespace wearscale::studies {

// ---- [dem]: the particles' material, their contact law, the engine ----------

/// [dem] material: "table-6.4" (the unitless targets of Table 6.4), a library
/// record or a [materials.define] name, with [dem] scaling_exponent s of
/// (6.57), restitution and poisson (ν ≤ 1/4, (6.52)); `default_name` when the
/// case names none.
dem::CohesiveMaterial dem_material(const Config& root, const std::string& default_name = "table-6.4");
/// [dem] law: the contact law between the particles, a registered name
/// (contact_law.hpp); [dem] friction: its Coulomb μ, read for the hooke law.
void read_contact_law(const Config& root, std::string& law, double& friction);
/// [dem] engine: the engine that integrates the study (engine.hpp): wearscale's
/// own, or LAMMPS (solvers/dem/lammps, in a build with liblammps-dev).
std::string read_engine(const Config& root);
/// Refuses a [dem] law other than the cohesive one: the studies that measure
/// the cohesive law's strengths (`study` names the study in the message).
void require_cohesive_law(const Config& root, const char* study);

/// The [dem] rows of a study's schema: the material (`materials`: the names
/// the study takes, for the --material help), its elastic and size-scaling
/// parameters, the contact law and the engine. The rows with a flag of their
/// own in one study name it here.
struct MaterialKeys {
  std::string materials;
  std::string fallback = "table-6.4";     ///< dem.material's default (dem_material's `default_name`)
  std::string poisson_flag = {};          ///< dem.poisson's alias
  std::string scaling_exponent_flag = {};  ///< dem.scaling_exponent's alias
};
Schema material_keys(const MaterialKeys& keys);

// ---- The keys several studies name alike: each reader beside its row ---------
// `c` is the study's table ([dem.junction], ...), `table` its name
// ("dem.junction").

/// time_step: Δt in the critical time step Δt_c (6.6), in (0, 1); 0.1.
double read_time_step(const Config& c);
KeySpec time_step_key(const std::string& table);
/// seed: of the random amorphous sample, in [0, 2^32); 1.
std::uint64_t read_seed(const Config& c);
KeySpec seed_key(const std::string& table, const std::string& doc = "seed of the amorphous sample");
/// d0: the mode of the particle diameters [m], required.
double read_d0(const Config& c);
KeySpec d0_key(const std::string& table);
/// largest: the largest particle diameter d_l ≥ d0 [m]; 1.25 d0 (§6.2.3).
double read_largest(const Config& c, double d0);
KeySpec largest_key(const std::string& table, const std::string& doc = "largest particle diameter");
/// velocity: the sliding velocity of the moving wall [m/s], in (0, 1000); 10.
double read_sliding_velocity(const Config& c);
KeySpec sliding_velocity_key(const std::string& table, const std::string& doc = "sliding velocity of the top wall");
/// pressure: the normal pressure p_N on the pressed wall [Pa], in [0, σ_m,N]
/// of `m` (beyond the normal strength the cohesive model holds no solid).
double read_pressure(const Config& c, double fallback, const dem::CohesiveMaterial& m);
KeySpec pressure_key(const std::string& table, const std::string& fallback,
                     const std::string& doc = "normal pressure on the top wall");
/// sliding_distance: how far the moving wall slides [m], > 0.
double read_sliding_distance(const Config& c, double fallback);
KeySpec sliding_distance_key(const std::string& table, const std::string& fallback);
/// box: the cell size [x, y, z] [m], three lengths > 0; none when not given.
std::optional<dem::Vec3> read_box(const Config& c);
KeySpec box_key(const std::string& table, const std::string& fallback, const std::string& doc);
/// wall_thickness: a wall's thickness in d0, in [1, 10]; 1.5 (§6.3).
double read_wall_thickness(const Config& c);
KeySpec wall_thickness_key(const std::string& table, const std::string& doc = "wall thickness in d0");
/// clearance: the gap left around a loose body, in d0, in [0, 1); 0.25.
double read_clearance(const Config& c);
KeySpec clearance_key(const std::string& table, const std::string& doc);
/// record_every: steps per history sample, ≥ 1; 200.
long read_record_every(const Config& c);
KeySpec record_every_key(const std::string& table);
/// relax_tolerance: the stress tolerance of the sample's relaxation (§6.2.2),
/// in E, in (0, 0.01); 1e-4.
double read_relax_tolerance(const Config& c);
KeySpec relax_tolerance_key(const std::string& table);
/// max_relax_steps: the relaxation's step limit, ≥ 0; 20000.
long read_max_relax_steps(const Config& c);
KeySpec max_relax_steps_key(const std::string& table);
/// dump_every: steps between OVITO snapshot frames, ≥ 0 (0: none).
long read_dump_every(const Config& c, long fallback);
KeySpec dump_every_key(const std::string& table, long fallback);

// ---- The sliding cell of the wear studies (§7.2, §7.3) ---------------------

/// The keys of the sliding cell (sliding_cell.hpp) the wear studies share,
/// read from [dem] and `c`, every value range-checked; the cell size is read
/// by each study (read_cell_box).
void read_sliding_cell(const Config& root, const Config& c, dem::SlidingCellSpec& cell);
/// The cell size L × W × H: W at least the largest particle, L at least
/// `min_length`, H at least `min_height`.
dem::Vec3 read_cell_box(const Config& c, const dem::SlidingCellSpec& cell, double default_length, double min_length,
                        double default_height, double min_height);
/// The rows of read_sliding_cell and read_cell_box's depth in `table`
/// ("dem.rough_shear"), the sliding distance defaulting to `slide_default`.
Schema sliding_keys(const std::string& table, const std::string& slide_default);

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

/// What the DEM studies share: case name "dem", folder out/dem-<study>, the
/// engine's ranks under mpirun, and the outputs their driver lists.
class DemStudy : public Study {
 public:
  std::string default_case_name() const override { return "dem"; }
  /// [dem] engine = "lammps": under mpirun one run over every rank (LAMMPS'
  /// domain decomposition), rank 0 writing the outputs and checkpoints.
  std::vector<std::string> prepare(Config& inputs) override;
  bool distributed() const override { return engine_ == "lammps"; }
  bool resumes_distributed() const override { return engine_ == "lammps"; }
  bool calls_mpi() const override { return engine_ == "lammps"; }
  void run_other_rank(const Config&) override;
  std::string default_output_dir() const override;

 protected:
  std::string engine_ = "wearscale";
  /// The driver's outputs (files, verdict) into the context; a sheared
  /// study's force history `<history>_history.csv` plotted.
  static void finish(const nlohmann::json& outputs, RunContext& context, const std::string& history);
};

}  // namespace wearscale::studies
