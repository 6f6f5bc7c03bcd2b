// wearscale.run: the one adapter between the Python module and the CLI's
// case runner (coupling::run_case). When the runner moves, this file is the
// only one to retarget.
#include <pybind11/stl.h>

#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/bem/contact_study.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_lock.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/coupling/case_runner.hpp"

namespace wearscale::python {

namespace {

// A [contact] case, as `wearscale contact CASE --json` runs it (apps/wearscale/cmd_contact.cpp).
std::string run_contact_case(const coupling::RunOptions& options) {
  Config cfg = Config::load(options.case_file);
  for (const auto& o : options.overrides) cfg.override_value(o);
  cfg.string_or("case.name", "contact");
  cfg.string_or("case.description", "");
  const std::string dir = cfg.string_or("output.dir", "out/contact");
  const std::filesystem::path out = options.output_dir ? *options.output_dir : std::filesystem::path(dir);
  const OutputLock lock = OutputLock::folder(out, "python: wearscale.run(" + options.case_file.string() + ")");
  OutputSet outputs(out, "summary.json");
  auto summary = bem::run_contact_study(cfg, out);
  summary["parameters"] = cfg.to_json();
  summary["output_dir"] = out.string();
  outputs.commit(summary);
  return summary.dump();
}

// Pipeline cases ([scale.*]) go through coupling::run_case, [contact] cases through the contact study.
std::string run(const coupling::RunOptions& options) {
  const Config cfg = Config::load(options.case_file);
  if (cfg.has("contact") && !cfg.has("scale")) return run_contact_case(options);
  return coupling::run_case(options).to_json().dump();
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("run_case", [](const std::string& case_file, const std::vector<std::string>& overrides,
                       std::optional<std::string> out, std::optional<std::string> resume, bool quiet) {
          coupling::RunOptions options;
          options.case_file = case_file;
          options.overrides = overrides;
          if (out) options.output_dir = *out;
          if (resume) options.resume_dir = *resume;
          std::string json;
          {
            py::gil_scoped_release release;
            log::set_level(quiet ? log::Level::Quiet : log::Level::Normal);
            json = run(options);
          }
          return json;
        }, py::arg("case_file"), py::arg("overrides") = std::vector<std::string>{}, py::arg("out") = py::none(),
        py::arg("resume") = py::none(), py::arg("quiet") = true,
        "Runs a case file as `wearscale run CASE --set K=V... [--out DIR] [--resume DIR] --json` (a [contact] case as "
        "`wearscale contact CASE --json`); returns the JSON text.");
  m.def("check_case", [](const std::string& case_file, const std::vector<std::string>& overrides) {
          coupling::RunOptions options;
          options.case_file = case_file;
          options.overrides = overrides;
          std::vector<std::string> dirs;
          for (const auto& d : coupling::check_case([&] { return Config::load(case_file); }, options)) dirs.push_back(d.string());
          return dirs;
        }, py::arg("case_file"), py::arg("overrides") = std::vector<std::string>{},
        "Every check run_case makes before writing anything; returns each run's output folder.");
}

}  // namespace wearscale::python
