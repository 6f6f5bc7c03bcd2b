#include "dem_case.hpp"

#include <algorithm>
#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/coupling/plots.hpp"
#ifdef WEARSCALE_DEM_LAMMPS
#include "wearscale/dem/lammps_engine.hpp"
#endif
#include "wearscale/io/csv.hpp"

namespace wearscale::studies {

using namespace dem;

// ---- Around a study's run ---------------------------------------------------

struct EngineRanks::Served {
#ifdef WEARSCALE_DEM_LAMMPS
  LammpsServedRun run;
#endif
};

EngineRanks::EngineRanks([[maybe_unused]] const std::string& engine) {
#ifdef WEARSCALE_DEM_LAMMPS
  if (engine == "lammps") served_ = std::make_unique<Served>();
#endif
}

EngineRanks::~EngineRanks() = default;

RunCheckpoints study_checkpoints(Checkpointer* checkpoints, const std::string& owner, DumpWriter* dump) {
  RunCheckpoints hooks;
  if (checkpoints == nullptr) return hooks;
  hooks.from = checkpoints->restored(owner);
  if (hooks.from != nullptr) {
    log::info("{}: resumes at step {} from {}", owner, hooks.from->step, checkpoints->file().string());
    if (dump != nullptr && hooks.from->has("dump.position")) {
      const auto& at = tallies(*hooks.from, "dump.position", 2);
      if (!dump->resume({hooks.from->text("dump.partial"), static_cast<std::uintmax_t>(at[0]),
                         static_cast<std::size_t>(at[1])}))
        log::warn("{}: the snapshots written before step {} are gone ({}); {} holds those from step {} on", owner,
                  hooks.from->step, hooks.from->text("dump.partial"), dump->final_path().string(), hooks.from->step);
    }
  }
  hooks.at_sample = [checkpoints, owner, dump](long step, const std::function<CheckpointState()>& make) {
    checkpoints->at_step(owner, step, [&] {
      CheckpointState st = make();
      if (dump != nullptr) {
        const auto at = dump->position();
        st.put_text("dump.partial", at.partial);
        st.put("dump.position", std::vector<double>{static_cast<double>(at.bytes), static_cast<double>(at.frames)});
      }
      return st;
    });
  };
  return hooks;
}

std::unique_ptr<Progress> progress_bar(const std::string& name, long planned, const RunCheckpoints& hooks) {
  auto bar = std::make_unique<Progress>(name, static_cast<double>(planned));
  if (hooks.from != nullptr) bar->start_at(static_cast<double>(hooks.from->step));
  return bar;
}

void SlidingDumps::operator()(const SlidingCell& cell, long step, long planned, const std::string& name,
                              const RunCheckpoints& hooks) {
  if (!bar) bar = progress_bar(name, planned, hooks);
  if (writer.frames() == 0) write(cell);
  bar->update(static_cast<double>(step));
  if (every > 0 && (step % every < cell_record_every || step == planned)) write(cell);
}

void SlidingDumps::write(const SlidingCell& cell) {
  const auto worn = cell.worn_flags();
  writer.write(cell.engine(), {{"worn", worn}});
}

std::vector<std::string> write_sliding_history(const std::vector<SlidingSample>& history, const std::filesystem::path& csv,
                                               H5Writer& h5, const std::string& title) {
  std::vector<double> t, s, ft, fn, ke, worn, sa_b, sa_t;
  for (const auto& h : history) {
    t.push_back(h.time);
    s.push_back(h.sliding);
    ft.push_back(h.tangential_force);
    fn.push_back(h.normal_force);
    ke.push_back(h.kinetic_energy);
    worn.push_back(h.worn);
    sa_b.push_back(h.roughness_bottom);
    sa_t.push_back(h.roughness_top);
  }
  const std::vector<std::string> names = {"time",           "sliding", "tangential_force", "normal_force",
                                          "kinetic_energy", "worn",    "roughness_bottom", "roughness_top"},
                                 units = {"s", "m", "N", "N", "J", "1", "m", "m"};
  write_csv(csv, names, {t, s, ft, fn, ke, worn, sa_b, sa_t}, units, {title});
  h5.write_table("/history", names, {t, s, ft, fn, ke, worn, sa_b, sa_t}, units);
  return {csv.string(), h5.final_path().string()};
}

// ---- DemStudy ---------------------------------------------------------------

Schema DemStudy::schema() const {
  Schema s = dem_keys().schema("dem");
  for (auto& row : study_keys()) s.push_back(std::move(row));
  return s;
}

DemInputs DemStudy::read_dem(const Config& root) const {
  DemInputs d;
  dem_keys().read(root.section("dem"), d.keys);
  d.material = dem_material(root, d.keys);
  return d;
}

// The engine alone: the others are read (and checked) by the run on rank 0.
std::vector<std::string> DemStudy::prepare(Config& inputs) {
  const Config c = inputs.section("dem");
  const auto& engine = dem_keys().key("engine");
  DemKeys k;
  engine.read(engine, c, k);
  require_engine(c, k.engine);
  engine_ = k.engine;
  return {};
}

void DemStudy::run_other_rank(const Config&) {
#ifdef WEARSCALE_DEM_LAMMPS
  serve_lammps_engines();
#endif
}

std::string DemStudy::default_output_dir() const {
  std::string leaf = name().substr(name().find('/') + 1);
  std::replace(leaf.begin(), leaf.end(), '_', '-');
  return "out/dem-" + leaf;
}

void DemStudy::finish(const nlohmann::json& outputs, RunContext& context, const std::string& history) {
  for (const auto& f : outputs["files"]) context.add_file(f.get<std::string>());
  if (!outputs.contains("verdict")) return;
  const std::string verdict = outputs["verdict"].get<std::string>();
  context.note("verdict", verdict);
  const auto& out = context.output_dir();
  // The title states the parameters, then the verdict.
  const std::string title =
      outputs.contains("caption") ? outputs["caption"].get<std::string>() + ": " + verdict : verdict;
  context.add_figure(coupling::junction_force_figure(history + "_force", title, out / (history + "_history.csv"), out));
}

}  // namespace wearscale::studies
