#pragma once
// What a scale sees of the run it is part of: the output folder, the run's
// HDF5 file, its checkpoints, the table of headline results and its figures.
#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "wearscale/coupling/figure.hpp"
#include "wearscale/io/checkpoint.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::coupling {

class RunContext {
 public:
  RunContext(std::filesystem::path output_dir, H5Writer& h5, bool show_progress = true,
             Checkpointer* checkpoints = nullptr)
      : dir_(std::move(output_dir)), h5_(h5), show_progress_(show_progress), checkpoints_(checkpoints) {}

  const std::filesystem::path& output_dir() const { return dir_; }
  /// The run's HDF5 file (run.h5): scales write their series and fields here.
  H5Writer& h5() { return h5_; }
  /// The run's checkpoints: a scale with a long loop restores from
  /// restored(<its id>) and calls at_step(<its id>, …) after each step
  /// (which also stops the loop on SIGINT). Without a checkpointer: one that
  /// never saves but still stops on SIGINT.
  Checkpointer& checkpoints();

  /// A headline figure: shown in the summary, printed by --json, stored in run.h5 /results.
  void report(const std::string& name, double value, const std::string& unit, const std::string& description);
  /// A file the run wrote besides run.h5 (CSV, XDMF, PNG), listed in the summary.
  void add_file(const std::filesystem::path& file) { files_.push_back(file); }
  /// A figure of the run (in its folder), drawn with the run's others by draw_figures().
  void add_figure(Figure figure) { figures_.push_back(std::move(figure)); }
  /// Draws the figures added so far, with one gnuplot (figure.hpp), and lists their files.
  void draw_figures();

  /// A field of the summary besides the headline figures, e.g. a DEM study's
  /// verdict: shown at the top level of summary.json.
  void note(const std::string& key, nlohmann::json value) { notes_[key] = std::move(value); }
  const nlohmann::json& notes() const { return notes_; }

  const nlohmann::json& results() const { return results_; }
  /// False when the run is one of several running side by side (a sweep).
  bool show_progress() const { return show_progress_; }
  const std::vector<std::filesystem::path>& files() const { return files_; }

 private:
  std::filesystem::path dir_;
  H5Writer& h5_;
  nlohmann::json results_ = nlohmann::json::object();
  nlohmann::json notes_ = nlohmann::json::object();
  std::vector<std::filesystem::path> files_;
  std::vector<Figure> figures_;
  bool show_progress_ = true;
  Checkpointer* checkpoints_ = nullptr;
  Checkpointer no_checkpoints_ = Checkpointer::disabled();
};

}  // namespace wearscale::coupling
