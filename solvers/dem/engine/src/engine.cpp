#include "wearscale/dem/engine.hpp"

#include <map>
#include <mutex>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/dem/simulation.hpp"

namespace wearscale::dem {

namespace {

// wearscale's own engine: a Simulation, whose calls the interface passes on.
class WearscaleEngine final : public Engine {
 public:
  explicit WearscaleEngine(EngineSetup setup)
      : sim_(std::move(setup.particles), setup.box, std::move(setup.law), setup.neighbors) {}

  std::string_view name() const override { return "wearscale"; }
  int add_wall(std::vector<std::size_t> members, WallMotion motion) override {
    return sim_.add_wall(std::move(members), motion);
  }
  void set_time_step(double dt) override { sim_.set_time_step(dt); }
  void set_global_damping(double c) override { sim_.set_global_damping(c); }
  void set_track_virial(bool on) override { sim_.set_track_virial(on); }
  void set_wall_velocity(int w, int axis, double velocity) override { sim_.wall(w).velocity[axis] = velocity; }
  void run(long steps, const std::function<void(long)>& each_step, StopInside inside) override {
    sim_.run(steps, each_step, inside == StopInside::Yes ? Simulation::StopInside::Yes : Simulation::StopInside::No);
  }
  void compute_forces() override { sim_.compute_forces(); }
  const Particles& particles() const override { return sim_.particles(); }
  const Box& box() const override { return sim_.box(); }
  const ContactLaw& law() const override { return sim_.law(); }
  const Wall& wall(int w) const override { return sim_.wall(w); }
  std::size_t wall_count() const override { return sim_.wall_count(); }
  double time_step() const override { return sim_.time_step(); }
  long step_count() const override { return sim_.step_count(); }
  double time() const override { return sim_.time(); }
  const std::vector<SymTensor>& virial() const override { return sim_.virial(); }
  double kinetic_energy() const override { return sim_.kinetic_energy(); }
  bool history_of_touching_pairs_only() const override {
    return sim_.neighbor_list().history_of_touching_pairs_only();
  }
  void save_state(CheckpointState& out) const override { sim_.save_state(out); }
  void restore_state(const CheckpointState& in) override { sim_.restore_state(in); }

 private:
  Simulation sim_;
};

std::unique_ptr<Engine> make_wearscale(EngineSetup setup) { return std::make_unique<WearscaleEngine>(std::move(setup)); }

std::mutex g_mutex;
std::map<std::string, EngineFactory>& engines() {
  static std::map<std::string, EngineFactory> table{{"wearscale", &make_wearscale}};
  return table;
}

}  // namespace

void register_engine(const std::string& name, EngineFactory make) {
  std::lock_guard lock(g_mutex);
  engines()[name] = make;
}

std::vector<std::string> engine_names() {
  std::lock_guard lock(g_mutex);
  std::vector<std::string> names;
  for (const auto& [name, make] : engines()) names.push_back(name);
  return names;
}

std::unique_ptr<Engine> make_engine(std::string_view name, EngineSetup setup) {
  EngineFactory make = nullptr;
  {
    std::lock_guard lock(g_mutex);
    if (auto it = engines().find(std::string(name)); it != engines().end()) make = it->second;
  }
  if (make == nullptr) {
    if (name == "lammps")
      throw InputError("DEM engine 'lammps': this build has no LAMMPS engine (it is built when CMake finds Debian's "
                       "liblammps-dev, option WEARSCALE_DEM_LAMMPS); allowed here: " +
                       fmt::format("{}", fmt::join(engine_names(), ", ")));
    throw InputError(fmt::format("unknown DEM engine '{}'; allowed: {}", name, fmt::join(engine_names(), ", ")));
  }
  return make(std::move(setup));
}

double kinetic_energy(const Particles& p) {
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.wall[i] != no_wall) continue;
    e += 0.5 * p.mass[i] * dot(p.velocity[i], p.velocity[i]) + 0.5 / p.inv_inertia[i] * dot(p.omega[i], p.omega[i]);
  }
  return e;
}

}  // namespace wearscale::dem
