// The multiscale model of a case: its [scale.<kind>] tables, each run by a
// registered backend, ordered by what they consume and provide (coupling/).
#include <algorithm>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/output_set.hpp"
#include "wearscale/core/task_farm.hpp"
#include "wearscale/coupling/backend_keys.hpp"
#include "wearscale/coupling/pipeline.hpp"
#include "wearscale/coupling/plots.hpp"
#include "wearscale/studies/study.hpp"

namespace wearscale::studies {

namespace {

using namespace coupling;

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

// Every exchanged quantity's producer, in run.h5: one group per quantity and
// the whole table as the root's "provenance" attribute.
void write_exchange_provenance(const Exchange& exchange, H5Writer& h5) {
  nlohmann::json provenance = nlohmann::json::object();
  for (const auto& key : exchange.keys()) {
    const auto p = exchange.provenance(key).to_json();
    provenance[key.to_string()] = p;
    std::string subject = key.subject;  // "SiO2/Si" would nest groups: store it as "SiO2-Si"
    std::replace(subject.begin(), subject.end(), '/', '-');
    const std::string group = "/exchange/" + to_string(key.what) + "/" + subject;
    h5.set_attribute(group, "producer", p["scale"].get<std::string>() + "/" + p["backend"].get<std::string>());
    h5.set_attribute(group, "provenance", p.dump());
  }
  h5.set_attribute("/", "provenance", provenance.dump(1));
}

class PipelineStudy final : public Study {
 public:
  std::string name() const override { return "pipeline"; }
  std::string summary() const override {
    return "the multiscale model of a case: its [scale.<kind>] backends in the order their quantities need";
  }
  Schema schema() const override {
    Schema schema = {{"scale.<kind>.backend", "string", "see `wearscale backends`", "", "", "the backend of a scale", ""}};
    for (auto& k : coupling::materials_schema()) schema.push_back(std::move(k));
    for (auto& k : material_schema()) schema.push_back(std::move(k));
    // Each backend's keys, its name before the meaning (two backends of a kind may share a key).
    for (const auto& info : scale_registry().list())
      for (auto& k : backend_schema(info.kind, info.name))
        if (!k.key.ends_with(".backend")) {
          k.doc = info.name + ": " + k.doc;
          schema.push_back(std::move(k));
        }
    return schema;
  }
  std::string default_case_name() const override { return ""; }  // a case names itself

  std::vector<std::string> prepare(Config& inputs) override {
    case_name_ = inputs.string("case.name");
    pipeline_ = build_pipeline(inputs);
    inputs.reject_unknown_keys();
    return pipeline_.ids();
  }

  // Under mpirun, when a scale farms ensembles (the junction runs of
  // nano/dem): rank 0 runs the pipeline, the other ranks serve its ensembles.
  bool distributed() const override { return pipeline_.farms_ensembles(); }
  bool has_ensembles() const override { return pipeline_.farms_ensembles(); }
  double estimated_cost() const override { return pipeline_.estimated_cost(); }
  void run_other_rank(const Config& /*inputs*/) override { mpi::serve_ensembles(); }

  void run(const Config& inputs, RunContext& context) override {
    const mpi::ServedRun served;  // under mpirun: the other ranks serve; this rank runs the scales alone
    Exchange exchange;
    pipeline_.run(exchange, context);
    write_exchange_provenance(exchange, context.h5());
    const auto friction = context.output_dir() / "friction.csv";
    if (std::filesystem::exists(OutputSet::readable(friction)))
      context.add_figure(friction_figure("friction", run_title(inputs, case_name_), {{case_name_, friction}},
                                         context.output_dir()));
  }

  // The pin-on-disc curves of the runs side by side, and Fig. 9.25 for a sweep over the oxide's thickness.
  std::vector<std::filesystem::path> finish_sweep(const SweepRuns& s) override {
    std::vector<Figure> figures;
    const std::string title = sweep_title(*s.probe, s.case_name, s.key, s.series_key);
    // A run's legend entry: its swept values in words ("SiO2 layer 0.5 µm, layer test tilted").
    auto label = [&](std::size_t k) {
      std::string text = parameter_words(*s.probe, s.key, s.values[k]);
      if (!s.series_key.empty()) text += ", " + parameter_words(*s.probe, s.series_key, s.series_values[k]);
      return text;
    };
    std::vector<FrictionCurve> curves, profiles;
    for (std::size_t k = 0; k < s.folders.size(); ++k) {
      if (std::filesystem::exists(s.folders[k] / "friction.csv")) curves.push_back({label(k), s.folders[k] / "friction.csv"});
      if (std::filesystem::exists(s.folders[k] / "disc_profile.csv"))
        profiles.push_back({label(k), s.folders[k] / "disc_profile.csv"});
    }
    // One figure for so many runs is no longer read: each run has its own.
    constexpr std::size_t most = 16;
    if (curves.size() > most || profiles.size() > most)
      log::info("{}: {} runs, too many for one figure: no friction_curves or disc_profiles figure (each run has its "
                "own friction figure)",
                s.output_dir.string(), std::max(curves.size(), profiles.size()));
    if (!curves.empty() && curves.size() <= most)
      figures.push_back(friction_figure("friction_curves", title, curves, s.output_dir));
    const std::string thickness = "materials.layer.thickness";
    if (!profiles.empty() && profiles.size() <= most) {
      // One oxide for all runs: its interface is drawn.
      const bool one_oxide = s.key != thickness && s.series_key != thickness && s.probe->has(thickness);
      const double h =
          one_oxide ? s.probe->number(thickness, Range::non_negative().or_infinite(), units::length) : 0.0;
      figures.push_back(disc_profiles_figure("disc_profiles", title, profiles, h, s.output_dir));
    }
    if (s.key == thickness && s.numeric_values &&
        std::find(s.result_names.begin(), s.result_names.end(), "mu_mean") != s.result_names.end()) {
      // A table per series value, in the order of the runs.
      std::vector<SweepTable> tables;
      const std::size_t per_table = s.tables.empty() ? 0 : s.folders.size() / s.tables.size();
      for (std::size_t t = 0; t < s.tables.size(); ++t)
        tables.push_back({s.series_key.empty() ? s.tables[t].first
                                               : parameter_words(*s.probe, s.series_key, s.series_values[t * per_table]),
                          s.tables[t].second});
      figures.push_back(friction_vs_thickness_figure("friction_vs_thickness", title, tables, s.output_dir));
    }
    return draw_figures(s.output_dir, figures);
  }

 private:
  Pipeline pipeline_;
  std::string case_name_;
};

}  // namespace
}  // namespace wearscale::studies

WEARSCALE_STUDY(PipelineStudy)
