#include "wearscale/dem/lammps_engine.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <thread>
#include <type_traits>

#include <fmt/format.h>

#include "lammps_system.hpp"
#include "lmptype.h"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/mpi.hpp"
#include "wearscale/dem/cohesive_law.hpp"
#include "wearscale/dem/engine.hpp"
#include "wearscale/dem/hooke_law.hpp"

namespace wearscale::dem {

namespace {

using lammps::AtomTable;
using lammps::GatheredState;
using lammps::LammpsSystem;
using lammps::LawConfig;
using lammps::RunFailure;
using lammps::SystemConfig;
using lammps::WallSlot;

// --- MPI for a process that was not launched by mpirun ------------------------

std::once_flag g_mpi_once;

void finalize_mpi() {
  int finalized = 0;
  MPI_Finalized(&finalized);
  if (finalized == 0) MPI_Finalize();
}

// LAMMPS needs MPI: a process started on its own initialises it here (with
// threads allowed to call it, for engines side by side), and finalises it at exit.
void ensure_mpi() {
  std::call_once(g_mpi_once, [] {
    int initialised = 0;
    MPI_Initialized(&initialised);
    if (initialised != 0) return;
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_MULTIPLE, &provided);
    std::atexit(finalize_mpi);
  });
}

// --- Messages from rank 0 to the serving ranks ---------------------------------

constexpr int kTagCall = 7201;
// The layout of the state save_state() writes (2: the global damping in lammps.clock).
constexpr const char* state_format = "wearscale-lammps-engine-2";

enum class Call : int {
  Create = 1, AddWall, SetTimeStep, SetDamping, SetTrackVirial, SetWallVelocity, Run, ComputeForces, Save,
  Restore, Destroy, End
};

class Writer {
 public:
  template <class T>
  void put(const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    buf_.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  template <class T>
  void put_all(const std::vector<T>& v) {
    put(static_cast<std::uint64_t>(v.size()));
    buf_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  std::string& bytes() { return buf_; }

 private:
  std::string buf_;
};

class Reader {
 public:
  explicit Reader(const std::string& buf) : buf_(buf) {}
  template <class T>
  T get() {
    T v;
    std::memcpy(&v, buf_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  template <class T>
  std::vector<T> get_all() {
    const auto n = get<std::uint64_t>();
    std::vector<T> v(n);
    std::memcpy(v.data(), buf_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
    return v;
  }

 private:
  const std::string& buf_;
  std::size_t at_ = 0;
};

void put_material(Writer& w, const CohesiveMaterial& m) {
  for (double v : {m.young, m.poisson, m.tensile_strength, m.shear_strength, m.surface_energy, m.scaling_exponent,
                   m.restitution, m.density})
    w.put(v);
}
CohesiveMaterial get_material(Reader& r) {
  CohesiveMaterial m;
  m.name = "pair";
  for (double* v : {&m.young, &m.poisson, &m.tensile_strength, &m.shear_strength, &m.surface_energy,
                    &m.scaling_exponent, &m.restitution, &m.density})
    *v = r.get<double>();
  return m;
}

void put_config(Writer& w, const SystemConfig& c) {
  w.put(c.box);
  const LawConfig& l = c.law;
  w.put(static_cast<int>(l.kind));
  w.put(l.types);
  w.put(l.cohesion);
  w.put(l.tangential);
  for (double v : {l.k_n, l.k_t, l.gamma_n, l.gamma_t, l.friction}) w.put(v);
  w.put(static_cast<std::uint64_t>(l.materials.size()));
  for (const auto& m : l.materials) put_material(w, m);
  w.put(c.neighbors);
  w.put(c.time_step);
  w.put(c.damping);
  w.put(c.track_virial);
}
SystemConfig get_config(Reader& r) {
  SystemConfig c;
  c.box = r.get<Box>();
  LawConfig& l = c.law;
  l.kind = static_cast<LawConfig::Kind>(r.get<int>());
  l.types = r.get<int>();
  l.cohesion = r.get<bool>();
  l.tangential = r.get<bool>();
  for (double* v : {&l.k_n, &l.k_t, &l.gamma_n, &l.gamma_t, &l.friction}) *v = r.get<double>();
  const auto n = r.get<std::uint64_t>();
  for (std::uint64_t k = 0; k < n; ++k) l.materials.push_back(get_material(r));
  c.neighbors = r.get<NeighborSettings>();
  c.time_step = r.get<double>();
  c.damping = r.get<double>();
  c.track_virial = r.get<bool>();
  return c;
}

// The particle table travels in one broadcast per array.
template <class T>
void broadcast_all(std::vector<T>& v, MPI_Comm comm) {
  std::uint64_t n = v.size();
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, comm);
  v.resize(n);
  const std::size_t bytes = n * sizeof(T);
  constexpr std::size_t chunk = std::size_t{1} << 30;
  for (std::size_t at = 0; at < bytes; at += chunk)
    MPI_Bcast(reinterpret_cast<char*>(v.data()) + at, static_cast<int>(std::min(chunk, bytes - at)), MPI_BYTE, 0, comm);
}

void broadcast_atoms(AtomTable& a, MPI_Comm comm) {
  std::uint64_t n = a.count;
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, comm);
  a.count = n;
  broadcast_all(a.x, comm);
  broadcast_all(a.v, comm);
  broadcast_all(a.omega, comm);
  broadcast_all(a.radius, comm);
  broadcast_all(a.mass, comm);
  broadcast_all(a.type, comm);
  broadcast_all(a.image, comm);
}

void put_slot(Writer& w, const WallSlot& s) { w.put(s); }  // trivially copyable: motion, mass, state
WallSlot get_slot(Reader& r) { return r.get<WallSlot>(); }

// Rank 0's end of the served run: the job's communicator (a duplicate) while one lives.
struct Served {
  MPI_Comm comm = MPI_COMM_NULL;
  int size = 1;
  long next_id = 1;
};
Served g_served;

// What a call asks of the serving ranks: the call, the engine and its arguments.
void tell_servers(Call call, long id, const std::string& arguments) {
  if (g_served.comm == MPI_COMM_NULL) return;
  Writer w;
  w.put(static_cast<int>(call));
  w.put(id);
  std::string message = std::move(w.bytes());
  message += arguments;
  for (int r = 1; r < g_served.size; ++r)
    MPI_Send(message.data(), static_cast<int>(message.size()), MPI_CHAR, r, kTagCall, g_served.comm);
}

// --- What a call does on every rank ---------------------------------------------

// Run: the steps, what stopped them, and the particles onto rank 0.
RunFailure run_and_gather(LammpsSystem& s, long steps, const std::function<void()>& each_step, GatheredState& out) {
  const RunFailure failure = s.run(steps, each_step);
  s.gather(0, out);
  return failure;
}

// --- The engine (rank 0, or a process alone) -------------------------------------

LawConfig law_config(const ContactLaw& law) {
  LawConfig c;
  if (const auto* cohesive = dynamic_cast<const CohesiveLaw*>(&law)) {
    c.kind = LawConfig::Kind::Cohesive;
    c.types = static_cast<int>(cohesive->materials().size());
    for (int a = 0; a < c.types; ++a)
      for (int b = 0; b < c.types; ++b)
        c.materials.push_back(cohesive->pair_material(static_cast<std::size_t>(a), static_cast<std::size_t>(b)));
    c.cohesion = cohesive->cohesion;
    c.tangential = cohesive->tangential;
    return c;
  }
  if (const auto* hooke = dynamic_cast<const HookeLaw*>(&law)) {
    c.kind = LawConfig::Kind::Hooke;
    c.k_n = hooke->k_n;
    c.k_t = hooke->k_t;
    c.gamma_n = hooke->gamma_n;
    c.gamma_t = hooke->gamma_t;
    c.friction = hooke->friction;
    return c;
  }
  throw InputError(fmt::format("DEM engine 'lammps': no LAMMPS pair style for the contact law '{}'; allowed: "
                               "cohesive, hooke",
                               law.name()));
}

int pack_image(const std::array<std::int32_t, 3>& image, std::int64_t id) {
  for (int a = 0; a < 3; ++a)
    if (image[static_cast<std::size_t>(a)] <= -IMGMAX || image[static_cast<std::size_t>(a)] >= IMGMAX)
      throw InputError(fmt::format("DEM engine 'lammps': particle {} has crossed {} periods along {}; LAMMPS counts "
                                   "at most ±{}",
                                   id, image[static_cast<std::size_t>(a)], "xyz"[a], IMGMAX - 1));
  return ((image[0] + IMGMAX) & IMGMASK) | (((image[1] + IMGMAX) & IMGMASK) << IMGBITS) |
         (((image[2] + IMGMAX) & IMGMASK) << IMG2BITS);
}

class LammpsEngine final : public Engine {
 public:
  explicit LammpsEngine(EngineSetup setup)
      : mirror_(std::move(setup.particles)), box_(setup.box), law_(std::move(setup.law)) {
    if (!law_) throw InputError("DEM system: no contact law");
    const NeighborSettings& nb = setup.neighbors;
    if (!(nb.skin > 0.0)) throw InputError(fmt::format("DEM neighbour skin = {}; allowed: > 0", nb.skin));
    if (nb.every < 0) throw InputError(fmt::format("DEM neighbour rebuild interval = {}; allowed: ≥ 0", nb.every));
    const Particles& p = mirror_;
    double largest = 0.0;
    for (double r : p.radius) largest = std::max(largest, 2.0 * r);
    for (int a = 0; a < 3; ++a)
      if (box_.periodic[static_cast<std::size_t>(a)] && box_.length()[a] < largest)
        throw InputError(fmt::format("DEM box: periodic length {:.4g} along {} is shorter than the largest particle "
                                     "diameter {:.4g} (a particle would overlap itself); allowed: ≥ {:.4g}",
                                     box_.length()[a], "xyz"[a], largest, largest));
    SystemConfig config;
    config.box = box_;
    config.law = law_config(*law_);
    config.neighbors = nb;
    touching_only_ = nb.history_of_touching_pairs_only;
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.material[i] >= config.law.types && config.law.kind == LawConfig::Kind::Cohesive)
        throw InputError(fmt::format("DEM engine 'lammps': particle {} has material {} of a table of {}", p.id[i],
                                     int(p.material[i]), config.law.types));
    if (config.law.kind == LawConfig::Kind::Hooke) config.law.types = 1;
    AtomTable atoms;
    atoms.count = p.size();
    atoms.x.reserve(3 * p.size());
    for (std::size_t i = 0; i < p.size(); ++i) {
      for (int a = 0; a < 3; ++a) {
        atoms.x.push_back(p.position[i][a]);
        atoms.v.push_back(p.velocity[i][a]);
        atoms.omega.push_back(p.omega[i][a]);
      }
      atoms.radius.push_back(p.radius[i]);
      atoms.mass.push_back(p.mass[i]);
      atoms.type.push_back(config.law.kind == LawConfig::Kind::Hooke ? 1 : int(p.material[i]) + 1);
      atoms.image.push_back(pack_image(p.image[i], p.id[i]));
    }
    ensure_mpi();
    MPI_Comm comm = MPI_COMM_SELF;
    if (LammpsServedRun::active()) {
      comm = g_served.comm;
      id_ = g_served.next_id++;
      Writer w;
      put_config(w, config);
      tell_servers(Call::Create, id_, w.bytes());
      broadcast_atoms(atoms, comm);
    }
    system_ = std::make_unique<LammpsSystem>(comm, std::move(config), atoms);
    served_ = comm != MPI_COMM_SELF;
  }

  ~LammpsEngine() override {
    if (served_ && LammpsServedRun::active()) tell_servers(Call::Destroy, id_, {});
  }

  std::string_view name() const override { return "lammps"; }

  int add_wall(std::vector<std::size_t> members, WallMotion motion) override {
    auto& p = mirror_;
    const int index = static_cast<int>(walls_.size());
    Wall w;
    w.motion = motion;
    double mass = 0.0;
    for (std::size_t i : members) {
      if (i >= p.size()) throw InputError("DEM wall: particle index out of range");
      mass += p.mass[i];
    }
    if (motion.kind == WallMotion::Kind::Pressure && !(motion.area > 0.0))
      throw InputError("DEM pressure wall: loaded area must be > 0");
    w.mass = motion.mass > 0.0 ? motion.mass : mass;
    if (motion.kind == WallMotion::Kind::Velocity) w.velocity = motion.velocity;
    if (motion.kind == WallMotion::Kind::Pressure) {
      w.velocity = motion.velocity;
      w.velocity[motion.axis] = 0.0;
    }
    for (std::size_t i : members) {
      p.wall[i] = static_cast<std::int16_t>(index);
      p.omega[i] = {};
      p.velocity[i] = w.velocity;
    }
    w.members = std::move(members);
    WallSlot slot{0, motion, w.mass, w.velocity, {}, {}};
    if (served_) {
      Writer a;
      std::vector<std::uint64_t> list(w.members.begin(), w.members.end());
      a.put_all(list);
      put_slot(a, slot);
      tell_servers(Call::AddWall, id_, a.bytes());
    }
    system_->add_wall(w.members, slot);
    walls_.push_back(std::move(w));
    return index;
  }

  void set_time_step(double dt) override {
    if (!(dt > 0.0) || !std::isfinite(dt)) throw InputError(fmt::format("DEM time step = {}; allowed: > 0", dt));
    call_with(Call::SetTimeStep, dt);
    system_->set_time_step(dt);
  }
  void set_global_damping(double c) override {
    call_with(Call::SetDamping, c);
    system_->set_damping(c);
  }
  void set_track_virial(bool on) override {
    call_with(Call::SetTrackVirial, on);
    system_->set_track_virial(on);
  }
  void set_wall_velocity(int w, int axis, double velocity) override {
    if (served_) {
      Writer a;
      a.put(w);
      a.put(axis);
      a.put(velocity);
      tell_servers(Call::SetWallVelocity, id_, a.bytes());
    }
    system_->set_wall_velocity(w, axis, velocity);
    walls_[static_cast<std::size_t>(w)].velocity[axis] = velocity;
  }

  void run(long steps, const std::function<void(long)>& each_step, StopInside) override {
    throw_if_interrupted(fmt::format("dem (step {})", step_count()));
    if (!(system_->config().time_step > 0.0)) throw InputError("DEM: set a time step before running");
    if (steps <= 0) return;
    call_with(Call::Run, steps);
    std::function<void()> observe;
    if (each_step)
      observe = [&] {
        take_walls();
        each_step(system_->steps());
      };
    const RunFailure failure = run_and_gather(*system_, steps, observe, gathered_);
    take_gathered();
    if (failure.kind != RunFailure::none) fail(failure);
  }

  void compute_forces() override {
    call_with(Call::ComputeForces, 0);
    system_->compute_forces();
    system_->gather(0, gathered_);
    take_gathered();
  }

  const Particles& particles() const override { return mirror_; }
  const Box& box() const override { return box_; }
  const ContactLaw& law() const override { return *law_; }
  const Wall& wall(int w) const override { return walls_[static_cast<std::size_t>(w)]; }
  std::size_t wall_count() const override { return walls_.size(); }
  double time_step() const override { return system_->config().time_step; }
  long step_count() const override { return system_->steps(); }
  double time() const override { return system_->time(); }
  const std::vector<SymTensor>& virial() const override { return virial_; }
  double kinetic_energy() const override { return dem::kinetic_energy(mirror_); }
  bool history_of_touching_pairs_only() const override { return touching_only_; }

  void save_state(CheckpointState& out) const override {
    if (served_) tell_servers(Call::Save, id_, {});
    const std::string bytes = system_->write_restart(0);
    // The restart file's bytes as doubles (kept bit for bit), its length first.
    std::vector<double> words((bytes.size() + sizeof(double) - 1) / sizeof(double), 0.0);
    if (!bytes.empty()) std::memcpy(words.data(), bytes.data(), bytes.size());
    out.put_text("lammps.format", state_format);
    out.put("lammps.restart_bytes", static_cast<double>(bytes.size()));
    out.put("lammps.restart", words);
    int ranks = 1;
    MPI_Comm_size(served_ ? g_served.comm : MPI_COMM_SELF, &ranks);
    // The global damping too: a driver changes it between runs (the oxide
    // asperity's settling ends undamped), and a restart file does not hold it.
    out.put("lammps.clock", std::vector<double>{static_cast<double>(system_->steps()), system_->time(),
                                                static_cast<double>(ranks), system_->config().damping});
    std::vector<double> walls;
    for (const auto& w : system_->walls())
      for (const Vec3* v : {&w.velocity, &w.force, &w.displacement})
        for (int a = 0; a < 3; ++a) walls.push_back((*v)[a]);
    out.put("lammps.walls", walls);
  }

  void restore_state(const CheckpointState& in) override {
    if (in.has("lammps.format") && in.text("lammps.format") == "wearscale-lammps-engine-1")
      throw InputError(fmt::format("{}: lammps.format = wearscale-lammps-engine-1, a state without its global damping "
                                   "(it cannot continue bit for bit); allowed: {}: run the study again from the start",
                                   in.origin, state_format));
    if (!in.has("lammps.format") || in.text("lammps.format") != state_format)
      throw InputError(fmt::format("{}: not a state of the LAMMPS engine (a run of another engine continues with "
                                   "its own: set the engine it ran with)",
                                   in.origin));
    const auto length = static_cast<std::size_t>(in.scalar("lammps.restart_bytes"));
    const auto& words = in.array("lammps.restart");
    if (words.size() * sizeof(double) < length) throw InputError(fmt::format("{}: lammps.restart is cut short", in.origin));
    const auto& clock = in.array("lammps.clock");
    const auto& walls = in.array("lammps.walls");
    if (clock.size() != 4 || !std::isfinite(clock[3]) || clock[3] < 0.0 || walls.size() != 9 * walls_.size())
      throw InputError(fmt::format("{}: not the LAMMPS engine state of this system ({} walls)", in.origin, walls_.size()));
    int ranks = 1;
    MPI_Comm_size(served_ ? g_served.comm : MPI_COMM_SELF, &ranks);
    if (static_cast<int>(clock[2]) != ranks)
      log::warn("the LAMMPS engine's state was saved on {} rank(s) and continues on {}: the continuation is a valid "
                "run, not the same bits as the one that stopped",
                static_cast<int>(clock[2]), ranks);
    std::string bytes(length, '\0');
    if (length > 0) std::memcpy(bytes.data(), words.data(), length);
    std::vector<WallSlot> slots = system_->walls();
    for (std::size_t w = 0; w < slots.size(); ++w) {
      Vec3* v[] = {&slots[w].velocity, &slots[w].force, &slots[w].displacement};
      for (int k = 0; k < 3; ++k)
        for (int a = 0; a < 3; ++a) (*v[k])[a] = walls[9 * w + 3 * static_cast<std::size_t>(k) + static_cast<std::size_t>(a)];
    }
    const auto steps = static_cast<long>(clock[0]);
    if (served_) {
      Writer a;
      a.put(steps);
      a.put(clock[1]);
      a.put(static_cast<std::uint64_t>(slots.size()));
      for (const auto& s : slots) put_slot(a, s);
      tell_servers(Call::Restore, id_, a.bytes());
    }
    system_->restore(0, bytes);
    system_->set_clock(steps, clock[1], slots);
    set_global_damping(clock[3]);
    system_->gather(0, gathered_);
    take_gathered();
    take_walls();
  }

 private:
  template <class T>
  void call_with(Call call, const T& argument) {
    if (!served_) return;
    Writer a;
    a.put(argument);
    tell_servers(call, id_, a.bytes());
  }

  void take_walls() {
    const auto& slots = system_->walls();
    for (std::size_t w = 0; w < walls_.size(); ++w) {
      walls_[w].velocity = slots[w].velocity;
      walls_[w].force = slots[w].force;
      walls_[w].displacement = slots[w].displacement;
    }
  }

  void take_gathered() {
    auto& p = mirror_;
    const GatheredState& g = gathered_;
    for (std::size_t i = 0; i < p.size(); ++i) {
      p.position[i] = {g.x[3 * i], g.x[3 * i + 1], g.x[3 * i + 2]};
      p.velocity[i] = {g.v[3 * i], g.v[3 * i + 1], g.v[3 * i + 2]};
      p.omega[i] = {g.omega[3 * i], g.omega[3 * i + 1], g.omega[3 * i + 2]};
      p.force[i] = {g.force[3 * i], g.force[3 * i + 1], g.force[3 * i + 2]};
      p.torque[i] = {g.torque[3 * i], g.torque[3 * i + 1], g.torque[3 * i + 2]};
      p.image[i] = {g.image[3 * i], g.image[3 * i + 1], g.image[3 * i + 2]};
    }
    if (g.virial.size() == 6 * p.size()) {
      virial_.resize(p.size());
      for (std::size_t i = 0; i < p.size(); ++i) std::copy_n(&g.virial[6 * i], 6, virial_[i].begin());
    } else {
      virial_.clear();
    }
    take_walls();
  }

  [[noreturn]] void fail(const RunFailure& f) const {
    const double dt = time_step();
    if (f.kind == RunFailure::skin)
      throw NumericalError("dem (lammps engine)", f.step, fmt::format("velocity of particle {}", f.tag),
                           fmt::format("it would move {:.3g} in one step of {:.3g}, more than the neighbour skin; the "
                                       "time step is unstable (keep it a fraction of Δt_c = √(2m/k_N): 0.1 Δt_c = "
                                       "{:.3g} here)",
                                       f.value, dt, 0.1 * law_->critical_time_step(mirror_)));
    throw NumericalError("dem (lammps engine)", f.step, fmt::format("velocity of particle {}", f.tag),
                         fmt::format("became NaN or infinite; the time step {:.3g} is likely too large (0.1 Δt_c "
                                     "= √(2m/k_N)/10 = {:.3g} here)",
                                     dt, 0.1 * law_->critical_time_step(mirror_)));
  }

  Particles mirror_;
  Box box_;
  std::unique_ptr<ContactLaw> law_;
  bool touching_only_ = false;
  std::vector<Wall> walls_;
  std::vector<SymTensor> virial_;
  GatheredState gathered_;
  std::unique_ptr<LammpsSystem> system_;
  long id_ = 0;
  bool served_ = false;
};

std::unique_ptr<Engine> make_lammps(EngineSetup setup) { return std::make_unique<LammpsEngine>(std::move(setup)); }

// --- The serving ranks ---------------------------------------------------------------

using Systems = std::map<long, std::unique_ptr<LammpsSystem>>;

// One of rank 0's calls, on this rank.
void serve_call(Call call, long id, Reader& r, MPI_Comm comm, Systems& systems) {
  GatheredState unused;
  if (call == Call::Create) {
    SystemConfig config = get_config(r);
    AtomTable atoms;
    broadcast_atoms(atoms, comm);
    systems[id] = std::make_unique<LammpsSystem>(comm, std::move(config), atoms);
    return;
  }
  if (call == Call::Destroy) {
    systems.erase(id);
    return;
  }
  LammpsSystem& s = *systems.at(id);
  switch (call) {
    case Call::AddWall: {
      const auto list = r.get_all<std::uint64_t>();
      const WallSlot slot = get_slot(r);
      s.add_wall(std::vector<std::size_t>(list.begin(), list.end()), slot);
      break;
    }
    case Call::SetTimeStep: s.set_time_step(r.get<double>()); break;
    case Call::SetDamping: s.set_damping(r.get<double>()); break;
    case Call::SetTrackVirial: s.set_track_virial(r.get<bool>()); break;
    case Call::SetWallVelocity: {
      const int w = r.get<int>(), axis = r.get<int>();
      s.set_wall_velocity(w, axis, r.get<double>());
      break;
    }
    case Call::Run: run_and_gather(s, r.get<long>(), {}, unused); break;
    case Call::ComputeForces:
      s.compute_forces();
      s.gather(0, unused);
      break;
    case Call::Save: s.write_restart(0); break;
    case Call::Restore: {
      const long steps = r.get<long>();
      const double time = r.get<double>();
      std::vector<WallSlot> slots(r.get<std::uint64_t>());
      for (auto& slot : slots) slot = get_slot(r);
      s.restore(0, {});
      s.set_clock(steps, time, slots);
      s.gather(0, unused);
      break;
    }
    default: break;
  }
}

void serve(MPI_Comm comm) {
  Systems systems;
  std::string message;
  for (;;) {
    // Wait for rank 0's next call, polling ever more slowly (0.1 to 20 ms):
    // a blocking receive would spin a core while rank 0 computes alone.
    int flag = 0, wait = 100;
    MPI_Status status;
    for (;;) {
      MPI_Iprobe(0, kTagCall, comm, &flag, &status);
      if (flag != 0) break;
      std::this_thread::sleep_for(std::chrono::microseconds(wait));
      wait = std::min(2 * wait, 20000);
    }
    int bytes = 0;
    MPI_Get_count(&status, MPI_CHAR, &bytes);
    message.resize(static_cast<std::size_t>(bytes));
    MPI_Recv(message.data(), bytes, MPI_CHAR, 0, kTagCall, comm, MPI_STATUS_IGNORE);
    Reader r(message);
    const auto call = static_cast<Call>(r.get<int>());
    const long id = r.get<long>();
    if (call == Call::End) return;
    // A call that fails here fails on rank 0 alike (its checks are
    // collective), which reports it; this rank waits for the next one.
    try {
      serve_call(call, id, r, comm, systems);
    } catch (const std::exception&) {
    }
  }
}

}  // namespace

void register_lammps_engine() { register_engine("lammps", &make_lammps); }

std::string lammps_engine_version() {
  ensure_mpi();
  return "LAMMPS " + lammps::library_version();
}

LammpsServedRun::LammpsServedRun() {
  if (!mpi::active() || mpi::size() <= 1) return;
  MPI_Comm_dup(MPI_COMM_WORLD, &g_served.comm);
  MPI_Comm_size(g_served.comm, &g_served.size);
  g_served.next_id = 1;
  serving_ = true;
}

LammpsServedRun::~LammpsServedRun() {
  if (!serving_) return;
  tell_servers(Call::End, 0, {});
  MPI_Comm_free(&g_served.comm);
  g_served = {};
}

bool LammpsServedRun::active() { return g_served.comm != MPI_COMM_NULL && mpi::size() > 1; }

void serve_lammps_engines() {
  if (!mpi::active() || mpi::size() <= 1 || mpi::rank() == 0) return;
  MPI_Comm comm = MPI_COMM_NULL;
  MPI_Comm_dup(MPI_COMM_WORLD, &comm);
  serve(comm);
  MPI_Comm_free(&comm);
}

bool lammps_engines_on_threads() {
  int initialised = 0;
  MPI_Initialized(&initialised);
  if (initialised == 0) return true;
  int provided = 0;
  MPI_Query_thread(&provided);
  return provided == MPI_THREAD_MULTIPLE;
}

}  // namespace wearscale::dem
