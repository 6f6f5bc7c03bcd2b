#include "wearscale/studies/runner_keys.hpp"

namespace wearscale::studies {

namespace {
// The keys of a view on a table: read through `table` on `c.section(prefix)`.
template <class Spec>
void append(Schema& out, const KeyTable<Spec>& table, const std::string& prefix) {
  for (auto& row : table.schema(prefix)) out.push_back(std::move(row));
}
}  // namespace

const KeyTable<CaseKeys>& case_keys() {
  using K = CaseKeys;
  static const auto table =
      KeyTable<K>()
          .string("case.name", &K::name, "name of the case: its summary's and, by default, its output folder's")
          .computed_text([](const K& k) { return k.default_name; }, "the study's name; the pipeline: required")
          .required_when([](const K& k) { return k.default_name.empty(); })
          .string("case.study", &K::study, "the study the case runs (a `wearscale studies` name)")
          .required()
          .read_if([](const Config& c, const K&) { return c.has("case.study"); })
          .fallback("pipeline with [scale.*] tables, else the study its one top-level table names")
          .string("case.description", &K::description, "one line on what the case is (kept in run.h5's case)")
          .fallback("\"\"")
          .string("output.dir", &K::output_dir, "output folder (--out overrides it)")
          .computed_text([](const K& k) { return k.default_dir.empty() ? "out/" + k.name : k.default_dir; },
                         "out/<case name>, or the study's own");
  return table;
}

const KeyTable<RunKeys>& run_keys() {
  using K = RunKeys;
  static const auto table =
      KeyTable<K>()
          .number("checkpoint_interval", [](K& k) -> double& { return k.checkpoints.interval; },
                  Range::non_negative(), units::time, "wall-clock time between checkpoints; 0: never by time")
          .integer("checkpoint_steps", [](K& k) -> long& { return k.checkpoints.every_steps; }, Range::non_negative(),
                   "solver steps between checkpoints; 0: never by steps")
          .choice("fft_planning", &K::fft_planning,
                  std::vector<std::pair<std::string, PlanRigor>>{{"measure", PlanRigor::Measure},
                                                                 {"estimate", PlanRigor::Estimate}},
                  "FFTW plans measured (fastest) or estimated (no planning time, results alike to rounding)")
          .integer("gather_limit", &K::gather_limit, Range::at_least(1),
                   "grid points rank 0 gathers under mpirun (the contact study's fields); above it every rank writes "
                   "its rows");
  return table;
}

const KeyTable<SweepKeys>& sweep_keys() {
  using K = SweepKeys;
  const auto has_series = [](const Config& c, const K&) { return c.has("series"); };
  static const auto table =
      KeyTable<K>()
          .string("key", &K::key, "the swept key, a key the case gives (\"scale.macro.velocity\")")
          .required()
          .texts("values", &K::values, "its values, one run each (numbers, or strings such as \"8 mm/s\")")
          .string("table", &K::table, "file name of the sweep's table in its output folder")
          .boolean("parallel", &K::parallel, "runs side by side over the threads or ranks")
          .string("series.key", &K::series_key, "a second key: the whole sweep once per value of it")
          .required()
          .read_if(has_series)
          .texts("series.values", &K::series_values, "the second key's values")
          .read_if(has_series);
  return table;
}

Schema runner_schema() {
  Schema out;
  append(out, case_keys(), "");
  append(out, run_keys(), "run");
  append(out, sweep_keys(), "sweep");
  return out;
}

}  // namespace wearscale::studies
