#include "wearscale/dem/simulation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>
#include <fmt/format.h>
#include <omp.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/dem/cell_order.hpp"

namespace wearscale::dem {

namespace {

// Below this many particles the force loop runs on one thread: the fork and
// the reduction of per-thread buffers would cost more than they save.
constexpr std::size_t parallel_threshold = 4096;

int force_threads(std::size_t n) {
  return n < parallel_threshold ? 1 : std::max(1, omp_get_max_threads());
}

}  // namespace

Simulation::Simulation(Particles particles, Box box, std::unique_ptr<ContactLaw> law, NeighborSettings neighbors)
    : particles_(std::move(particles)), box_(box), law_(std::move(law)), settings_(neighbors) {
  if (!law_) throw InputError("DEM system: no contact law");
  if (!(settings_.skin > 0.0))
    throw InputError(fmt::format("DEM neighbour skin = {}; allowed: > 0", settings_.skin));
  if (settings_.every < 0)
    throw InputError(fmt::format("DEM neighbour rebuild interval = {}; allowed: ≥ 0", settings_.every));
  for (int a = 0; a < 3; ++a)
    if (box_.periodic[static_cast<std::size_t>(a)] && !(box_.hi[a] > box_.lo[a]))
      throw InputError(fmt::format("DEM box: periodic axis {} has hi ≤ lo", "xyz"[a]));
  neighbors_.set_history_of_touching_pairs_only(settings_.history_of_touching_pairs_only);
  neighbors_.set_keep_build_positions(settings_.check_displacement);
}

int Simulation::add_wall(std::vector<std::size_t> members, WallMotion motion) {
  in_user_order();
  const auto index = static_cast<int>(walls_.size());
  Wall w;
  w.motion = motion;
  double mass = 0.0;
  for (std::size_t i : members) {
    if (i >= particles_.size()) throw InputError("DEM wall: particle index out of range");
    particles_.wall[i] = static_cast<std::int16_t>(index);
    particles_.omega[i] = {};
    mass += particles_.mass[i];
  }
  w.mass = motion.mass > 0.0 ? motion.mass : mass;
  w.members = std::move(members);
  if (motion.kind == WallMotion::Kind::Velocity) w.velocity = motion.velocity;
  if (motion.kind == WallMotion::Kind::Pressure) {
    w.velocity = motion.velocity;
    w.velocity[motion.axis] = 0.0;
    if (!(motion.area > 0.0)) throw InputError("DEM pressure wall: loaded area must be > 0");
  }
  for (std::size_t i : w.members) particles_.velocity[i] = w.velocity;
  walls_.push_back(std::move(w));
  map_walls();
  forces_valid_ = false;
  since_build_ = -1;  // frozen pairs changed: rebuild
  return index;
}

void Simulation::set_time_step(double dt) {
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw InputError(fmt::format("DEM time step = {}; allowed: > 0", dt));
  dt_ = dt;
}

void Simulation::reset() {
  in_user_order();  // the user's numbering from here on, until the next renumbering
  user_of_.clear();
  slot_of_.clear();
  wall_slots_.clear();
  neighbors_.clear();
  forces_valid_ = false;
  since_build_ = -1;
}

double Simulation::reach() const {
  double max_radius = 0.0;
  for (double r : particles_.radius) max_radius = std::max(max_radius, r);
  return law_->pull_off_distance(max_radius);
}

void Simulation::throw_wrong_law() const {
  throw InputError(fmt::format("DEM system: its contact law is '{}', not the one this operation needs", law_->name()));
}

void Simulation::rebuild() {
  auto& p = particles_;
  const std::size_t n = p.size();
  int farthest = 0;  // the most periods a particle was wrapped by
#pragma omp parallel for schedule(static) reduction(max : farthest) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a) {
      const int wraps = box_.wrap(a, p.position[i][a]);
      p.image[i][static_cast<std::size_t>(a)] -= wraps;
      farthest = std::max(farthest, std::abs(wraps));
    }
  if (farthest >= NeighborList::max_wraps)
    throw NumericalError("dem", step_, "neighbour list",
                         fmt::format("a particle crossed {} periods of the box since the last neighbour build (at most "
                                     "{} allowed): it has missed its contacts on the way; rebuild the list more often "
                                     "or lower the time step",
                                     farthest, NeighborList::max_wraps - 1));
  if (settings_.renumber_every > 0 && neighbors_.builds() % settings_.renumber_every == 0) renumber();
  neighbors_.build(p, box_, reach(), settings_.skin, law_->history_size());
  prepare_pairs();
  since_build_ = 0;
}

// Cells of the largest radius (cell_order.hpp: about half the largest
// diameter numbers best), z, then y, then x, stable within a cell.
void Simulation::renumber() {
  const std::size_t n = particles_.size();
  if (n == 0) return;
  double max_radius = 0.0;
  for (double r : particles_.radius) max_radius = std::max(max_radius, r);
  const auto order = cell_order(particles_.position, max_radius);
  std::vector<std::uint32_t> from(order.begin(), order.end()), new_index(n);
  for (std::size_t k = 0; k < n; ++k) new_index[from[k]] = static_cast<std::uint32_t>(k);
  neighbors_.renumber(new_index, [&](double* h) { law_->reverse_history(h); });
  in_slots_ = true;  // the arrays are in slot order (the user's, the first time)
  gather(from);
  if (user_of_.empty()) {
    user_of_ = std::move(from);
  } else {
    std::vector<std::uint32_t> user(n);
    for (std::size_t k = 0; k < n; ++k) user[k] = user_of_[from[k]];
    user_of_.swap(user);
  }
  slot_of_.resize(n);
  for (std::size_t k = 0; k < n; ++k) slot_of_[user_of_[k]] = static_cast<std::uint32_t>(k);
  map_walls();
  ++renumberings_;
}

namespace {
// v reordered through `scratch`: new[k] = old[from[k]].
template <class T>
void reorder_array(std::vector<T>& v, const std::uint32_t* from, std::vector<std::byte>& scratch) {
  static_assert(std::is_trivially_copyable_v<T>);
  const std::size_t n = v.size();
  if (scratch.size() < n * sizeof(T)) scratch.resize(n * sizeof(T));
  std::byte* out = scratch.data();
  const T* in = v.data();
#pragma omp parallel for schedule(static) if (n >= 4096)
  for (std::size_t k = 0; k < n; ++k) std::memcpy(out + k * sizeof(T), in + from[k], sizeof(T));
  std::memcpy(static_cast<void*>(v.data()), out, n * sizeof(T));
}
}  // namespace

void Simulation::gather(const std::vector<std::uint32_t>& from) const {
  const std::size_t n = particles_.size();
  particles_.for_each_array([&](auto& v) {
    if (v.size() == n) reorder_array(v, from.data(), reorder_scratch_);
  });
  if (virial_.size() == n) reorder_array(virial_, from.data(), reorder_scratch_);
}

void Simulation::in_slot_order() const {
  if (in_slots_ || user_of_.empty()) return;
  gather(user_of_);  // slot k ← user's user_of_[k]
  in_slots_ = true;
}

void Simulation::in_user_order() const {
  if (!in_slots_) return;
  gather(slot_of_);  // user's u ← slot slot_of_[u]
  in_slots_ = false;
}

void Simulation::map_walls() {
  wall_slots_.clear();
  if (user_of_.empty()) return;
  wall_slots_.resize(walls_.size());
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    wall_slots_[w].resize(walls_[w].members.size());
    for (std::size_t m = 0; m < walls_[w].members.size(); ++m) wall_slots_[w][m] = slot_of_[walls_[w].members[m]];
  }
}

void Simulation::prepare_pairs() {
  const std::size_t n = particles_.size();
  const int threads = force_threads(n);
  // The two-colour blocks of the threaded pair loop (pair_loop.hpp): at
  // least the list's reach in index, and enough of them for the threads.
  std::size_t span = 0;
  const auto& off = neighbors_.offsets();
  const auto& nb = neighbors_.neighbors();
  if (off.size() == n + 1) {
#pragma omp parallel for schedule(static) reduction(max : span) if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i)
      for (std::uint32_t k = off[i]; k < off[i + 1]; ++k) span = std::max<std::size_t>(span, nb[k] - i);
  }
  // Blocks of about equal pair counts (walls' rows have fewer pairs), each
  // but the last at least `span` rows; up to 32 of them, a multiple of 4,
  // so that two or four threads get as many blocks of each colour (with 5,
  // one of two threads ran two of the three even blocks while the other
  // waited). When the rows' reach leaves fewer than asked, 4 fewer are cut.
  // Not a function of the thread count: the same sums on any.
  const std::size_t rows = std::max<std::size_t>(span, 64);
  const std::size_t most = std::min<std::size_t>(32, n / rows);
  block_start_.clear();
  if (threads > 1 && most >= 4 && most >= 2 * static_cast<std::size_t>(threads)) {
    const std::size_t pairs = off.back();
    auto cut = [&](std::size_t want) {  // the blocks made
      block_start_.assign(1, 0);
      for (std::size_t b = 1; b < want; ++b) {
        const auto target = static_cast<std::uint32_t>(pairs * b / want);
        auto e = static_cast<std::size_t>(std::lower_bound(off.begin(), off.end(), target) - off.begin());
        e = std::max(e, block_start_.back() + rows);
        if (e >= n) break;
        block_start_.push_back(e);
      }
      block_start_.push_back(n);
      return block_start_.size() - 1;
    };
    std::size_t want = most - most % 4;
    while (cut(want) != want && want > 4) want -= 4;
    if (block_start_.size() - 1 < 2 * static_cast<std::size_t>(threads)) block_start_.clear();
  }
  const std::size_t buffers = threads > 1 && block_start_.empty() ? static_cast<std::size_t>(threads) : 1;
  thread_force_.resize(buffers);
  thread_torque_.resize(buffers);
  thread_virial_.resize(buffers);
  for (std::size_t b = 1; b < buffers; ++b) {
    thread_force_[b].resize(n);
    thread_torque_[b].resize(n);
    if (track_virial_) thread_virial_[b].resize(n);
  }
  if (track_virial_) virial_.resize(n);
  law_->prepare(particles_, neighbors_);
}

void Simulation::compute_forces() {
  const SlotOrder order(*this);
  forces(false);
}

void Simulation::forces(bool advance, bool cleared) {
  if (since_build_ < 0 || neighbors_.offsets().size() != particles_.size() + 1) rebuild();
  if (track_virial_ && virial_.size() != particles_.size()) prepare_pairs();
  auto& p = particles_;
  const std::size_t n = p.size();
  const bool virial = track_virial_;
  if (!cleared) {
#pragma omp parallel for schedule(static) if (n >= parallel_threshold)
    for (std::size_t i = 0; i < n; ++i) {
      p.force[i] = {};
      p.torque[i] = {};
      if (virial) virial_[i] = {};
    }
  }
  neighbors_.shift_vectors(box_, shift_table_.data());
  PairLoop loop;
  loop.n = n;
  loop.offset = neighbors_.offsets().data();
  loop.neighbor = neighbors_.neighbors().data();
  loop.image = neighbors_.shifts().data();
  loop.shift = shift_table_.data();
  loop.history = neighbors_.history().data();
  loop.history_size = neighbors_.history_size();
  loop.x = p.position.data();
  loop.v = p.velocity.data();
  loop.w = p.omega.data();
  loop.radius = p.radius.data();
  loop.mass = p.mass.data();
  loop.force = p.force.data();
  loop.torque = p.torque.data();
  loop.virial = track_virial_ ? virial_.data() : nullptr;
  loop.thread_force = &thread_force_;
  loop.thread_torque = &thread_torque_;
  loop.thread_virial = &thread_virial_;
  loop.threads = force_threads(n);
  loop.block_start = block_start_.data();
  loop.blocks = block_start_.empty() ? 0 : block_start_.size() - 1;
  loop.dt = dt_;
  loop.advance = advance;
  law_->add_pair_forces(loop);
  if (global_damping_ > 0.0)
    for (std::size_t i = 0; i < n; ++i)
      if (p.wall[i] == no_wall) p.force[i] -= global_damping_ * p.velocity[i];
  for (std::size_t w = 0; w < walls_.size(); ++w) {
    Wall& wall = walls_[w];
    wall.force = {};
    for (std::size_t i : wall_slots(w)) wall.force += p.force[i];
  }
  forces_valid_ = true;
}

namespace {
double wall_acceleration(const Wall& w, const Vec3& velocity) {
  const auto& m = w.motion;
  const double load = -static_cast<double>(m.outward) * m.pressure * m.area;
  return (w.force[m.axis] + load - m.damping * velocity[m.axis]) / w.mass;
}
}  // namespace

// One pass over the particles for the kicks between two force evaluations
// (6.1): the second half-kick of the step whose forces are in, then the
// first half-kick and drift of the next. Run back to back (the run's steps,
// when nothing observes between them) they read each particle's force,
// velocity and masses once and the threads meet once; each part computes
// the bits it computes alone. The walls' half-kicks (pressed walls) come
// first, from their forces; their particles move with them in the same
// pass, each on the thread that integrates its stretch of particles.
void Simulation::kick(bool second, bool first, bool clear_forces) {
  auto& p = particles_;
  const std::size_t n = p.size();
  const double half = 0.5 * dt_;
  double max_v2 = 0.0;
  bool finite = true;
  const bool clear = first && clear_forces;
  const bool virial = clear && track_virial_;
  wall_moves_.resize(walls_.size());
  for (std::size_t wi = 0; wi < walls_.size(); ++wi) {
    const Wall& w = walls_[wi];
    Vec3 v = w.velocity;
    if (w.motion.kind == WallMotion::Kind::Pressure) {
      if (second) v[w.motion.axis] += half * wall_acceleration(w, v);
      if (first) v[w.motion.axis] += half * wall_acceleration(w, v);
    }
    wall_moves_[wi] = {v, dt_ * v};
  }
  const WallMove* moves = wall_moves_.data();
#pragma omp parallel for schedule(static) reduction(max : max_v2) reduction(&& : finite) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 f = p.force[i], tq = p.torque[i];
    if (clear) {
      p.force[i] = {};
      p.torque[i] = {};
      if (virial) virial_[i] = {};
    }
    if (p.wall[i] != no_wall) {
      if (first) {  // moves with its wall
        const WallMove& m = moves[p.wall[i]];
        p.position[i] += m.dx;
        p.velocity[i] = m.velocity;
      }
      continue;
    }
    Vec3 v = p.velocity[i], w = p.omega[i];
    if (second) {
      v += (half * p.inv_mass[i]) * f;
      w += (half * p.inv_inertia[i]) * tq;
      finite = finite && std::isfinite(v.x + v.y + v.z);
    }
    if (first) {
      v += (half * p.inv_mass[i]) * f;
      p.position[i] += dt_ * v;
      w += (half * p.inv_inertia[i]) * tq;
      max_v2 = std::max(max_v2, dot(v, v));
    }
    p.velocity[i] = v;
    p.omega[i] = w;
  }
  if (second) {
    if (!finite) {
      std::size_t bad = 0;
      for (std::size_t i = 0; i < n; ++i)
        if (p.wall[i] == no_wall && !std::isfinite(p.velocity[i].x + p.velocity[i].y + p.velocity[i].z)) {
          bad = i;
          break;
        }
      throw NumericalError("dem", step_ + 1, fmt::format("velocity of particle {}", p.id[bad]),
                           fmt::format("became NaN or infinite; the time step {:.3g} is likely too large (0.1 Δt_c "
                                       "= √(2m/k_N)/10 = {:.3g} here)",
                                       dt_, 0.1 * law_->critical_time_step(p)));
    }
    ++step_;
    time_ += dt_;
  }
  for (std::size_t wi = 0; wi < walls_.size(); ++wi) {
    walls_[wi].velocity = wall_moves_[wi].velocity;
    if (first) walls_[wi].displacement += wall_moves_[wi].dx;
  }
  if (!first) return;
  if (std::sqrt(max_v2) * dt_ > settings_.skin || !std::isfinite(max_v2)) {
    std::size_t worst = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (p.wall[i] == no_wall && !(dot(p.velocity[i], p.velocity[i]) < max_v2)) worst = i;
    throw NumericalError(
        "dem", step_ + 1, fmt::format("velocity of particle {}", p.id[worst]),
        fmt::format("it moved {:.3g} in one step of {:.3g}, more than the neighbour skin {:.3g}; the "
                    "time step is unstable (keep it a fraction of Δt_c = √(2m/k_N): 0.1 Δt_c = {:.3g} here)",
                    std::sqrt(max_v2) * dt_, dt_, settings_.skin, 0.1 * law_->critical_time_step(p)));
  }
}

bool Simulation::clears_forces_in_kick() const {
  // The half-kick zeroes what it has read, unless the virials are yet to be sized.
  return !track_virial_ || virial_.size() == particles_.size();
}

void Simulation::start_step() {
  if (!(dt_ > 0.0)) throw InputError("DEM: set a time step before running");
  if (!forces_valid_) forces(false);
  forces_valid_ = false;  // from here until the step's forces are in
}

void Simulation::finish_step_forces() {
  ++since_build_;
  if ((settings_.every > 0 && since_build_ >= settings_.every) ||
      (settings_.check_displacement && neighbors_.moved_beyond_half_skin(particles_)))
    rebuild();
  forces(true, clears_forces_in_kick());
}

void Simulation::step() {
  const SlotOrder order(*this);
  start_step();
  kick(false, true, clears_forces_in_kick());
  finish_step_forces();
  kick(true, false, false);
}

void Simulation::run(long steps, const std::function<void(long)>& observe, StopInside inside) {
  const auto start = std::chrono::steady_clock::now();
  const bool within = inside == StopInside::Yes;
  // SIGINT/SIGTERM: at the start of a call, so that a study running in
  // chunks stops between them (where it checkpoints); unless the caller
  // says so, also every 1024 steps and, in a call that has run for more
  // than 5 s, at the next step or the one after (1024 steps of 500 000
  // particles take minutes). A chunk of a checkpointing driver runs to its
  // end: stopped inside it, the run would lose everything since its last
  // checkpoint.
  auto stops_before = [&](long s) {
    if (s == 0) return true;
    if (!within) return false;
    return s % 1024 == 0 ||
           (interrupt_requested() && std::chrono::steady_clock::now() - start > std::chrono::seconds(5));
  };
  // Between two steps that nobody observes, the second half-kick of one and
  // the first of the next are one pass (kick); the call's last step ends
  // with its own, so the state between calls is the same.
  const SlotOrder order(*this);
  bool kicked = false;  // this step's first half-kick is done
  for (long s = 0; s < steps; ++s) {
    in_slot_order();  // an observer may have asked for the user's
    if (!kicked) {
      if (stops_before(s)) throw_if_interrupted(fmt::format("dem (step {})", step_));
      start_step();
      kick(false, true, clears_forces_in_kick());
    }
    finish_step_forces();
    kicked = !observe && s + 1 < steps && !stops_before(s + 1);
    if (kicked) {
      start_step();  // the next one's: its forces are in
      kick(true, true, clears_forces_in_kick());
    } else {
      kick(true, false, false);
    }
    if (observe) observe(step_);
  }
}

double Simulation::stable_time_step() const {
  in_user_order();
  return 0.1 * law_->critical_time_step(particles_);
}

double Simulation::kinetic_energy() const {
  in_user_order();  // summed in the user's order: the same bits renumbered or not
  const auto& p = particles_;
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.wall[i] != no_wall) continue;
    e += 0.5 * p.mass[i] * dot(p.velocity[i], p.velocity[i]) +
         0.5 / p.inv_inertia[i] * dot(p.omega[i], p.omega[i]);
  }
  return e;
}

double Simulation::potential_energy() const {
  const SlotOrder order(*this);  // the list's numbering
  const auto& p = particles_;
  const auto& off = neighbors_.offsets();
  const auto& nb = neighbors_.neighbors();
  const auto& sh = neighbors_.shifts();
  const auto& hist = neighbors_.history();
  if (off.size() != p.size() + 1) return 0.0;
  std::array<Vec3, PeriodicImages::max_count> shifts{};
  neighbors_.shift_vectors(box_, shifts.data());
  const auto stride = static_cast<std::size_t>(neighbors_.history_size());
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::uint32_t k = off[i]; k < off[i + 1]; ++k) {
      const std::uint32_t j = nb[k];
      const double r = norm(p.position[j] + shifts[sh[k]] - p.position[i]);
      const double delta = r - p.radius[i] - p.radius[j];
      law_->add_pair_energy(p, i, j, k, delta, hist.data() + stride * k, e);
    }
  return e;
}

Vec3 Simulation::momentum() const {
  in_user_order();
  Vec3 m{};
  for (std::size_t i = 0; i < particles_.size(); ++i) m += particles_.mass[i] * particles_.velocity[i];
  return m;
}

}  // namespace wearscale::dem
