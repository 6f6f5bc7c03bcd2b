#pragma once
// Checkpoints: the state of a long run, saved now and then so that a killed
// run can be resumed (`wearscale run CASE --resume DIR`). One file per run,
// `checkpoint.h5` in its output folder, always replaced atomically (written
// under a temporary name, then renamed), so a kill at any moment leaves the
// previous complete checkpoint. It holds one state per owner (a scale:
// "macro/bem-pin-on-disc"), the fingerprint of the case it belongs to, and
// the FFTW plans in use (wisdom), so a resumed run computes with the same
// transforms as the run it continues. The file records its format version
// and a SHA-256 checksum of everything it holds: a damaged checkpoint (flipped
// bytes, a truncated copy, a dataset rewritten by another tool) or one of
// another format is refused (InputError), never resumed from.
//
// A solver that wants to be resumable saves what it needs into a
// CheckpointState (core/checkpoint_state.hpp: arrays of doubles, stored bit
// for bit) and restores from one; its backend calls at_step() after each step.
#include <chrono>
#include <filesystem>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "wearscale/core/checkpoint_state.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale {

/// When to save: by wall-clock time, by solver steps, or both (whichever
/// comes first). A pending SIGINT/SIGTERM always saves.
struct CheckpointPolicy {
  double interval = 600.0;  ///< wall-clock seconds between checkpoints; 0: never by time
  long every_steps = 0;     ///< solver steps between checkpoints; 0: never by steps
};

class Checkpointer {
 public:
  /// Checkpoints of one run into `file`. `fingerprint` identifies the case
  /// (the resolved parameters that determine the results, as JSON text).
  Checkpointer(std::filesystem::path file, std::string fingerprint, CheckpointPolicy policy);
  /// One that never saves; at_step() still honours interrupts.
  static Checkpointer disabled();

  /// Reads the checkpoint to resume from: InputError if it is not a wearscale
  /// checkpoint of this format, is damaged (checksum, types, shapes), or
  /// belongs to a case with other parameters (naming the first key that
  /// differs). Imports its FFTW wisdom.
  void load();
  /// The same from an open file (fuzzing, tests).
  void load(const H5Reader& file);
  /// The state `owner` saved before the run stopped, or nullptr.
  const CheckpointState* restored(const std::string& owner) const;

  /// Call after every step of a solver loop: saves make() when the policy
  /// says so; if SIGINT/SIGTERM is pending, saves and throws Interrupted.
  void at_step(const std::string& owner, long step, const std::function<CheckpointState()>& make);
  /// Saves `state` for `owner` now (with the other owners' last states).
  void save(const std::string& owner, CheckpointState state);
  /// Removes the checkpoint (the run has completed).
  void discard();

  bool enabled() const { return enabled_; }
  const std::filesystem::path& file() const { return file_; }
  long saves() const { return saves_; }
  double seconds_saving() const { return seconds_saving_; }

 private:
  Checkpointer() = default;
  void write() const;
  std::filesystem::path file_;
  std::string fingerprint_;
  CheckpointPolicy policy_;
  bool enabled_ = false;
  std::map<std::string, CheckpointState> states_;  // last saved (or restored) state per owner
  std::map<std::string, long> last_step_;
  std::chrono::steady_clock::time_point last_save_ = std::chrono::steady_clock::now();
  long saves_ = 0;
  double seconds_saving_ = 0.0;
};

/// The folder `--resume DIR` continues: InputError unless `resume` is a
/// folder and `out` (--out, empty if not given) names the same one.
std::filesystem::path resume_folder(const std::filesystem::path& resume, const std::filesystem::path& out);

/// A fresh run (no --resume) never discards the checkpoint of an unfinished
/// one: OutputError naming `checkpoint` (and how to continue) if it exists.
void require_fresh_start(const std::filesystem::path& checkpoint);

/// The fingerprint of a resolved case (JSON): the case without what does not
/// change its results ([run]: how often to checkpoint; [output]: where to
/// write; [sweep]: the sweep around a run), as JSON text.
std::string case_fingerprint(const nlohmann::json& parameters);

/// "key 'scale.macro.grid' was 64, is now 128": the first difference between
/// two resolved cases given as JSON text, or "" if they are equal or not JSON.
std::string describe_case_difference(const std::string& was, const std::string& now);

}  // namespace wearscale
