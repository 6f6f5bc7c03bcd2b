#include "wearscale/coupling/case_runner.hpp"

#include <chrono>
#include <ctime>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/config.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/hdf5_file.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/coupling/pipeline.hpp"

namespace wearscale::coupling {

nlohmann::json RunSummary::to_json() const {
  std::vector<std::string> names;
  for (const auto& f : files) names.push_back(f.string());
  return {{"case", case_name}, {"output_dir", output_dir.string()}, {"scales", scales},
          {"results", results}, {"files", names}, {"parameters", parameters}};
}

namespace {

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &tm);
  return buf;
}

Pipeline build_pipeline(const Config& cfg) {
  const auto& registry = scale_registry();
  const auto kinds = cfg.keys("scale");
  if (kinds.empty())
    throw InputError(fmt::format("{}: the case has no [scale.<kind>] table; known kinds: {}", cfg.source(),
                                 fmt::join(registry.kinds(), ", ")));
  Pipeline pipeline;
  for (const auto& kind : kinds) {
    const Config section = cfg.section("scale." + kind);
    const auto names = registry.names(kind);
    if (names.empty())
      throw cfg.error("scale." + kind, "unknown scale kind", fmt::format("{}", fmt::join(registry.kinds(), ", ")));
    const std::string backend = section.string("backend");
    if (!registry.contains(kind, backend))
      throw section.error("backend", "unknown backend", fmt::format("{}", fmt::join(names, ", ")));
    const ScaleSetup setup{kind, backend, section, cfg};
    pipeline.add(kind + "/" + backend, registry.create(kind, backend, setup));
  }
  pipeline.order();
  return pipeline;
}

}  // namespace

RunSummary run_case(const RunOptions& options) {
  Config cfg = Config::load(options.case_file);
  for (const auto& o : options.overrides) cfg.override_value(o);

  RunSummary summary;
  summary.case_name = cfg.string("case.name");
  cfg.string_or("case.description", "");
  const std::string case_dir = cfg.string_or("output.dir", "out/" + summary.case_name);
  summary.output_dir = options.output_dir ? *options.output_dir : std::filesystem::path(case_dir);
  // Every check on the case happens here, before anything is written.
  Pipeline pipeline = build_pipeline(cfg);
  cfg.reject_unknown_keys();
  summary.scales = pipeline.ids();
  summary.parameters = cfg.to_json();

  std::error_code ec;
  std::filesystem::create_directories(summary.output_dir, ec);
  if (ec)
    throw InputError(fmt::format("output folder {}: cannot create it: {}", summary.output_dir.string(), ec.message()));

  log::info("case '{}': {} → {}", summary.case_name, fmt::join(summary.scales, " → "), summary.output_dir.string());
  H5Writer h5(summary.output_dir / "run.h5");
  h5.set_attribute("/", "case_file", options.case_file.string());
  h5.set_attribute("/", "case_toml", cfg.to_toml());
  h5.set_attribute("/", "wearscale_version", WEARSCALE_VERSION);
  h5.set_attribute("/", "created", utc_now());

  RunContext context(summary.output_dir, h5);
  Exchange exchange;
  pipeline.run(exchange, context);

  nlohmann::json provenance = nlohmann::json::object();
  for (const auto& key : exchange.keys()) provenance[key.to_string()] = exchange.provenance(key).to_json();
  h5.set_attribute("/", "provenance", provenance.dump(1));
  for (const auto& [name, r] : context.results().items()) {
    h5.write_scalar("/results/" + name, r["value"].get<double>(), r["unit"].get<std::string>());
    h5.set_attribute("/results/" + name, "description", r["description"].get<std::string>());
  }
  summary.results = context.results();
  summary.files = context.files();
  h5.commit();
  summary.files.insert(summary.files.begin(), h5.final_path());
  write_file_atomically(summary.output_dir / "summary.json", summary.to_json().dump(2) + "\n");
  summary.files.push_back(summary.output_dir / "summary.json");
  return summary;
}

}  // namespace wearscale::coupling
