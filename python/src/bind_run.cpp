// wearscale.run: the Python front end of the one study runner
// (studies/runner.hpp), the same path as `wearscale run CASE --json`.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <csignal>
#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/io/config.hpp"
#include "wearscale/studies/runner.hpp"

namespace wearscale::python {

namespace {

// Ctrl-C during a run: Python's own SIGINT handler only sets a flag that the C++ loops never
// see, so a run would go on to its end. While a run started from the main thread goes, the
// CLI's handlers are in place instead (the run saves its checkpoint, removes its unfinished
// files and raises KeyboardInterrupt with the resume hint, as the CLI exits 130); Python's
// are put back afterwards. A run in another thread keeps Python's (signals go to the main one).
class RunSignals {
 public:
  RunSignals() {
    const auto threading = py::module_::import("threading");
    if (!threading.attr("current_thread")().is(threading.attr("main_thread")())) return;
    sigaction(SIGINT, nullptr, &int_);
    sigaction(SIGTERM, nullptr, &term_);
    clear_interrupt();
    install_interrupt_handlers();
    installed_ = true;
  }
  ~RunSignals() {
    if (!installed_) return;
    sigaction(SIGINT, &int_, nullptr);
    sigaction(SIGTERM, &term_, nullptr);
    clear_interrupt();
  }
  RunSignals(const RunSignals&) = delete;
  RunSignals& operator=(const RunSignals&) = delete;

 private:
  struct sigaction int_ {}, term_ {};
  bool installed_ = false;
};

}  // namespace

void bind_run(py::module_& m) {
  m.def("run_case", [](const std::filesystem::path& case_file, const std::vector<std::string>& overrides,
                       std::optional<std::filesystem::path> out, std::optional<std::filesystem::path> resume, bool quiet,
                       std::optional<std::string> case_text, std::optional<std::string> task) {
          studies::RunOptions options;
          options.case_file = case_file;
          options.case_text = std::move(case_text);
          options.overrides = overrides;
          options.task = std::move(task);
          if (out) options.output_dir = *out;
          if (resume) options.resume_dir = *resume;
          std::string json;
          const RunSignals signals;
          {
            py::gil_scoped_release release;
            // Under mpirun rank 0 speaks for the job, as the CLI's does.
            log::set_level(mpi::size() > 1 && !mpi::is_root() ? log::Level::Silent
                           : quiet                           ? log::Level::Quiet
                                                             : log::Level::Normal);
            json = studies::run_case(options).to_json().dump();
          }
          return json;
        }, py::arg("case_file"), py::arg("overrides") = std::vector<std::string>{}, py::arg("out") = py::none(),
        py::arg("resume") = py::none(), py::arg("quiet") = true, py::arg("case_text") = py::none(),
        py::arg("task") = py::none(),
        "Runs a case file (any study: the scale pipeline, [contact], [dem.*]) as `wearscale run CASE --set K=V... "
        "[--out DIR] [--resume DIR] [--task K/N] --json`; returns the JSON text. case_text: the case as TOML text "
        "instead (case_file then names it in messages; relative file names in it are relative to the working "
        "directory).");
  m.def("merge_shards", [](const std::filesystem::path& dir, bool quiet) {
          std::string json;
          const RunSignals signals;
          {
            py::gil_scoped_release release;
            log::set_level(quiet ? log::Level::Quiet : log::Level::Normal);
            json = studies::merge_shards(dir, "wearscale.merge('" + dir.string() + "')").to_json().dump();
          }
          return json;
        }, py::arg("dir"), py::arg("quiet") = true,
        "`wearscale merge DIR --json`: the outputs of an ensemble whose shards (task='K/N') ran into DIR; returns "
        "the JSON text.");
  m.def("inspect_case", [](const std::filesystem::path& case_file, const std::vector<std::string>& overrides,
                           std::optional<std::filesystem::path> out, std::optional<std::string> case_text) {
          studies::RunOptions options;
          options.case_file = case_file;
          options.case_text = std::move(case_text);
          options.overrides = overrides;
          if (out) options.output_dir = *out;
          std::string json, text;
          {
            py::gil_scoped_release release;
            const auto report = studies::inspect_case(studies::case_loader(options), options);
            json = report.to_json().dump();
            text = report.text();
          }
          return py::make_tuple(json, text);
        }, py::arg("case_file"), py::arg("overrides") = std::vector<std::string>{}, py::arg("out") = py::none(),
        py::arg("case_text") = py::none(),
        "`wearscale check CASE --set K=V... [--out DIR]`: the case checked as run_case reads it (every error at once), "
        "nothing run or written; returns (the JSON of `--json`, the text it prints).");
}

}  // namespace wearscale::python
