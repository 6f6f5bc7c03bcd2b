#include "wearscale/dem/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <fmt/format.h>
#include <omp.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/interrupt.hpp"

namespace wearscale::dem {

namespace {

// Below this many particles the force loop runs on one thread: the fork and
// the reduction of per-thread buffers would cost more than they save.
constexpr std::size_t parallel_threshold = 4096;

int force_threads(std::size_t n) {
  return n < parallel_threshold ? 1 : std::max(1, omp_get_max_threads());
}

void add_outer(SymTensor& w, const Vec3& d, const Vec3& f) {
  // ½ (d ⊗ f), symmetrised: the pair's share of the virial of each particle.
  w[0] += 0.5 * d.x * f.x;
  w[1] += 0.5 * d.y * f.y;
  w[2] += 0.5 * d.z * f.z;
  w[3] += 0.25 * (d.x * f.y + d.y * f.x);
  w[4] += 0.25 * (d.x * f.z + d.z * f.x);
  w[5] += 0.25 * (d.y * f.z + d.z * f.y);
}

// What a force law computes for one pair: the force on i (the force on j is
// its opposite) and its tangential part, which makes the torques.
struct PairForce {
  Vec3 force;
  Vec3 tangential;
  Vec3 normal;  // unit vector from i to j
  bool active;
};

struct PairState {
  Vec3 d;   // x_j − x_i (nearest image)
  Vec3 vi, vj, wi, wj;
  double ri, rj, mi, mj;
};

// LAMMPS pair gran/hooke/history, term by term (so that the benchmark does
// the same work and the same arithmetic as the reference decks).
inline PairForce hooke_pair(const HookeLaw& law, const PairState& s, double* hist, double dt,
                            bool advance) {
  PairForce out{};
  const double r2 = dot(s.d, s.d);
  const double radsum = s.ri + s.rj;
  if (r2 >= radsum * radsum) {
    hist[0] = hist[1] = hist[2] = 0.0;
    out.active = false;
    return out;
  }
  const Vec3 del = -s.d;  // x_i − x_j
  const double r = std::sqrt(r2);
  const double rinv = 1.0 / r;
  const double rsqinv = rinv * rinv;
  const Vec3 vr = s.vi - s.vj;
  const double vnnr = dot(vr, del);
  const Vec3 vn = del * (vnnr * rsqinv);
  const Vec3 vt = vr - vn;
  const Vec3 wr = (s.ri * s.wi + s.rj * s.wj) * rinv;
  const double meff = s.mi * s.mj / (s.mi + s.mj);
  const double damp = meff * law.gamma_n * vnnr * rsqinv;
  const double ccel = law.k_n * (radsum - r) * rinv - damp;
  const Vec3 vtr = vt + cross(del, wr);
  Vec3 shear{hist[0], hist[1], hist[2]};
  if (advance) shear += vtr * dt;
  const bool sheared = dot(shear, shear) != 0.0;  // LAMMPS tests |shear| != 0 before the rotation
  if (advance) shear -= del * (dot(shear, del) * rsqinv);
  const double damp_t = meff * law.gamma_t;
  Vec3 fs = -(law.k_t * shear + damp_t * vtr);
  const double fs2 = dot(fs, fs);
  const double fn = law.friction * std::fabs(ccel * r);
  if (fs2 > fn * fn) {  // Coulomb cap; square roots only when it bites
    if (sheared) {
      const double ratio = fn / std::sqrt(fs2);
      const Vec3 dv = vtr * (damp_t / law.k_t);
      shear = ratio * (shear + dv) - dv;
      fs *= ratio;
    } else {
      fs = {};
    }
  }
  hist[0] = shear.x;
  hist[1] = shear.y;
  hist[2] = shear.z;
  out.force = del * ccel + fs;
  out.tangential = fs;
  out.normal = s.d * rinv;
  out.active = true;
  return out;
}

// The cohesive force of §6.1: (6.2)-(6.5).
inline PairForce cohesive_pair_force(const CohesiveLaw& law, const CohesivePair& p,
                                     const PairState& s, double* hist, double dt, bool advance) {
  PairForce out{};
  const double r2 = dot(s.d, s.d);
  const double contact = s.ri + s.rj;
  const double range = law.cohesion ? contact + p.delta_f : contact;
  if (r2 >= range * range) {
    hist[0] = hist[1] = hist[2] = 0.0;
    out.active = false;
    return out;
  }
  const double r = std::sqrt(r2);
  const Vec3 n = s.d * (1.0 / r);
  const double delta_n = r - contact;
  const double f_n = law.cohesion ? normal_force(p, delta_n) : p.k_n * std::min(delta_n, 0.0);
  const Vec3 vrel = s.vi - s.vj + cross(s.ri * s.wi + s.rj * s.wj, n);
  const double v_n = dot(vrel, n);
  out.force = (f_n - p.c_n * v_n) * n;  // (6.2), normal part; positive f_n pulls i toward j
  if (law.tangential && p.k_t > 0.0) {
    // The sliding distance integrates the contact's tangential velocity and
    // is turned into the current tangent plane; the total tangential force,
    // spring and damping, is capped by F'_m,T (6.4)-(6.5), the spring
    // stretched back to match, as in the thesis' LAMMPS pair style
    // gran/cohesive/history (built on gran/hooke/history).
    const Vec3 v_t = vrel - v_n * n;
    Vec3 xi{hist[0], hist[1], hist[2]};
    if (advance) xi += v_t * dt;
    const bool sliding = dot(xi, xi) != 0.0;
    if (advance) xi -= dot(xi, n) * n;
    Vec3 f_t = -(p.k_t * xi + p.c_t * v_t);
    const double cap = tangential_cap(p, delta_n);  // (6.4)-(6.5)
    const double f2 = dot(f_t, f_t);
    if (f2 > cap * cap) {
      if (sliding) {
        const double ratio = cap / std::sqrt(f2);
        const Vec3 lag = v_t * (p.c_t / p.k_t);
        xi = ratio * (xi + lag) - lag;
        f_t *= ratio;
      } else {
        f_t = {};
      }
    }
    if (advance) {
      hist[0] = xi.x;
      hist[1] = xi.y;
      hist[2] = xi.z;
    }
    out.force += f_t;
    out.tangential = f_t;
  }
  out.normal = n;
  out.active = true;
  return out;
}

}  // namespace

Simulation::Simulation(Particles particles, Box box, ForceLaw law, NeighborSettings neighbors)
    : particles_(std::move(particles)), box_(box), law_(std::move(law)), settings_(neighbors) {
  if (!(settings_.skin > 0.0))
    throw InputError(fmt::format("DEM neighbour skin = {}; allowed: > 0", settings_.skin));
  if (settings_.every < 0)
    throw InputError(fmt::format("DEM neighbour rebuild interval = {}; allowed: ≥ 0", settings_.every));
  for (int a = 0; a < 3; ++a)
    if (box_.periodic[static_cast<std::size_t>(a)] && !(box_.hi[a] > box_.lo[a]))
      throw InputError(fmt::format("DEM box: periodic axis {} has hi ≤ lo", "xyz"[a]));
}

int Simulation::add_wall(std::vector<std::size_t> members, WallMotion motion) {
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
  neighbors_.clear();
  forces_valid_ = false;
  since_build_ = -1;
}

double Simulation::reach() const {
  if (const auto* c = std::get_if<CohesiveLaw>(&law_)) {
    if (!c->cohesion) return 0.0;
    double max_radius = 0.0;
    for (double r : particles_.radius) max_radius = std::max(max_radius, r);
    return c->reach(max_radius);
  }
  return 0.0;
}

void Simulation::rebuild() {
  auto& p = particles_;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 3; ++a) p.image[i][static_cast<std::size_t>(a)] -= box_.wrap(a, p.position[i][a]);
  neighbors_.build(p, box_, reach(), settings_.skin);
  prepare_pairs();
  since_build_ = 0;
}

void Simulation::prepare_pairs() {
  const std::size_t n = particles_.size();
  const int threads = force_threads(n);
  thread_force_.resize(static_cast<std::size_t>(threads));
  thread_torque_.resize(static_cast<std::size_t>(threads));
  thread_virial_.resize(static_cast<std::size_t>(threads));
  for (int t = 1; t < threads; ++t) {
    thread_force_[static_cast<std::size_t>(t)].resize(n);
    thread_torque_[static_cast<std::size_t>(t)].resize(n);
    if (track_virial_) thread_virial_[static_cast<std::size_t>(t)].resize(n);
  }
  if (track_virial_) virial_.resize(n);
  const auto* law = std::get_if<CohesiveLaw>(&law_);
  if (!law) {
    pair_params_.clear();
    return;
  }
  const auto& off = neighbors_.offsets();
  const auto& nb = neighbors_.neighbors();
  pair_params_.resize(neighbors_.pairs());
#pragma omp parallel for schedule(static) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = off[i]; k < off[i + 1]; ++k) pair_params_[k] = law->pair(particles_, i, nb[k]);
}

template <class Law, bool Virial>
void Simulation::pair_forces(const Law& law, bool advance) {
  auto& p = particles_;
  const std::size_t n = p.size();
  const auto& off = neighbors_.offsets();
  const auto& nb = neighbors_.neighbors();
  const auto& sh = neighbors_.shifts();
  double* hist = neighbors_.history().data();
  const int threads = force_threads(n);
  const double dt = dt_;
  const Vec3* x = p.position.data();
  const Vec3* v = p.velocity.data();
  const Vec3* w = p.omega.data();
  const double* rad = p.radius.data();
  const double* mass = p.mass.data();
  const Vec3* shift = shift_table_.data();

#pragma omp parallel num_threads(threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    Vec3* f = t == 0 ? p.force.data() : thread_force_[t].data();
    Vec3* tq = t == 0 ? p.torque.data() : thread_torque_[t].data();
    SymTensor* vir = nullptr;
    if constexpr (Virial) vir = t == 0 ? virial_.data() : thread_virial_[t].data();
    if (t != 0) {
      std::fill_n(f, n, Vec3{});
      std::fill_n(tq, n, Vec3{});
      if constexpr (Virial) std::fill_n(vir, n, SymTensor{});
    }
#pragma omp for schedule(static, 512)
    for (std::size_t i = 0; i < n; ++i) {
      PairState s;
      s.vi = v[i];
      s.wi = w[i];
      s.ri = rad[i];
      s.mi = mass[i];
      const Vec3 xi = x[i];
      Vec3 fi{}, ti{};
      for (std::uint32_t k = off[i]; k < off[i + 1]; ++k) {
        const std::uint32_t j = nb[k];
        s.d = x[j] + shift[sh[k]] - xi;
        s.vj = v[j];
        s.wj = w[j];
        s.rj = rad[j];
        s.mj = mass[j];
        PairForce pf;
        if constexpr (std::is_same_v<Law, HookeLaw>)
          pf = hooke_pair(law, s, hist + 3 * k, dt, advance);
        else
          pf = cohesive_pair_force(law, pair_params_[k], s, hist + 3 * k, dt, advance);
        if (!pf.active) continue;
        fi += pf.force;
        f[j] -= pf.force;
        const Vec3 arm = cross(pf.normal, pf.tangential);
        ti += s.ri * arm;
        tq[j] += s.rj * arm;
        if constexpr (Virial) {
          add_outer(vir[i], s.d, pf.force);
          add_outer(vir[j], s.d, pf.force);
        }
      }
      f[i] += fi;
      tq[i] += ti;
    }
  }
  if (threads > 1) {
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t t = 1; t < static_cast<std::size_t>(threads); ++t) {
        p.force[i] += thread_force_[t][i];
        p.torque[i] += thread_torque_[t][i];
        if constexpr (Virial)
          for (std::size_t c = 0; c < 6; ++c) virial_[i][c] += thread_virial_[t][i][c];
      }
  }
}

void Simulation::compute_forces() { forces(false); }

void Simulation::forces(bool advance) {
  if (since_build_ < 0 || neighbors_.offsets().size() != particles_.size() + 1) rebuild();
  if (track_virial_ && virial_.size() != particles_.size()) prepare_pairs();
  auto& p = particles_;
  const std::size_t n = p.size();
  std::fill(p.force.begin(), p.force.end(), Vec3{});
  std::fill(p.torque.begin(), p.torque.end(), Vec3{});
  if (track_virial_) std::fill(virial_.begin(), virial_.end(), SymTensor{});
  neighbors_.shift_vectors(box_, shift_table_.data());
  std::visit(
      [&](const auto& law) {
        using L = std::decay_t<decltype(law)>;
        if (track_virial_)
          pair_forces<L, true>(law, advance);
        else
          pair_forces<L, false>(law, advance);
      },
      law_);
  if (global_damping_ > 0.0)
    for (std::size_t i = 0; i < n; ++i)
      if (p.wall[i] == no_wall) p.force[i] -= global_damping_ * p.velocity[i];
  for (auto& wall : walls_) {
    wall.force = {};
    for (std::size_t i : wall.members) wall.force += p.force[i];
  }
  forces_valid_ = true;
}

namespace {
double wall_acceleration(const Wall& w) {
  const auto& m = w.motion;
  const double load = -static_cast<double>(m.outward) * m.pressure * m.area;
  return (w.force[m.axis] + load - m.damping * w.velocity[m.axis]) / w.mass;
}
}  // namespace

void Simulation::integrate_first_half() {
  auto& p = particles_;
  const std::size_t n = p.size();
  const double half = 0.5 * dt_;
  double max_v2 = 0.0;
#pragma omp parallel for schedule(static) reduction(max : max_v2) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    if (p.wall[i] != no_wall) continue;
    p.velocity[i] += (half * p.inv_mass[i]) * p.force[i];
    p.position[i] += dt_ * p.velocity[i];
    p.omega[i] += (half * p.inv_inertia[i]) * p.torque[i];
    max_v2 = std::max(max_v2, dot(p.velocity[i], p.velocity[i]));
  }
  for (auto& w : walls_) {
    if (w.motion.kind == WallMotion::Kind::Pressure) w.velocity[w.motion.axis] += half * wall_acceleration(w);
    const Vec3 dx = dt_ * w.velocity;
    w.displacement += dx;
    for (std::size_t i : w.members) {
      p.position[i] += dx;
      p.velocity[i] = w.velocity;
    }
  }
  if (std::sqrt(max_v2) * dt_ > settings_.skin || !std::isfinite(max_v2)) {
    std::size_t worst = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (p.wall[i] == no_wall && !(dot(p.velocity[i], p.velocity[i]) < max_v2)) worst = i;
    throw NumericalError(
        "dem", step_ + 1, fmt::format("velocity of particle {}", p.id[worst]),
        fmt::format("it moved {:.3g} in one step of {:.3g}, more than the neighbour skin {:.3g}; the "
                    "time step is unstable (keep it a fraction of Δt_c = √(2m/k_N): 0.1 Δt_c = {:.3g} here)",
                    std::sqrt(max_v2) * dt_, dt_, settings_.skin, stable_time_step()));
  }
}

void Simulation::integrate_second_half() {
  auto& p = particles_;
  const std::size_t n = p.size();
  const double half = 0.5 * dt_;
  bool finite = true;
#pragma omp parallel for schedule(static) reduction(&& : finite) if (n >= parallel_threshold)
  for (std::size_t i = 0; i < n; ++i) {
    if (p.wall[i] != no_wall) continue;
    p.velocity[i] += (half * p.inv_mass[i]) * p.force[i];
    p.omega[i] += (half * p.inv_inertia[i]) * p.torque[i];
    finite = finite && std::isfinite(p.velocity[i].x + p.velocity[i].y + p.velocity[i].z);
  }
  for (auto& w : walls_)
    if (w.motion.kind == WallMotion::Kind::Pressure) w.velocity[w.motion.axis] += half * wall_acceleration(w);
  if (!finite) {
    std::size_t bad = 0;
    for (std::size_t i = 0; i < n; ++i)
      if (!std::isfinite(p.velocity[i].x + p.velocity[i].y + p.velocity[i].z)) {
        bad = i;
        break;
      }
    throw NumericalError("dem", step_ + 1, fmt::format("velocity of particle {}", p.id[bad]),
                         fmt::format("became NaN or infinite; the time step {:.3g} is likely too large (0.1 Δt_c "
                                     "= √(2m/k_N)/10 = {:.3g} here)",
                                     dt_, stable_time_step()));
  }
}

void Simulation::step() {
  if (!(dt_ > 0.0)) throw InputError("DEM: set a time step before running");
  if (!forces_valid_) forces(false);
  integrate_first_half();
  ++since_build_;
  if ((settings_.every > 0 && since_build_ >= settings_.every) ||
      (settings_.check_displacement && neighbors_.moved_beyond_half_skin(particles_)))
    rebuild();
  forces(true);
  integrate_second_half();
  ++step_;
  time_ += dt_;
}

void Simulation::run(long steps, const std::function<void(long)>& observe) {
  for (long s = 0; s < steps; ++s) {
    // SIGINT/SIGTERM: at the start of a call, so that a study running in
    // chunks stops between them (where it checkpoints), and every 1024 steps.
    if (s % 1024 == 0) throw_if_interrupted(fmt::format("dem (step {})", step_));
    step();
    if (observe) observe(step_);
  }
}

double Simulation::stable_time_step() const {
  if (const auto* cohesive = std::get_if<CohesiveLaw>(&law_)) return 0.1 * cohesive->critical_time_step(particles_);
  double lightest = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < particles_.size(); ++i)
    if (particles_.wall[i] == no_wall) lightest = std::min(lightest, particles_.mass[i]);
  return 0.1 * critical_time_step(lightest, std::get<HookeLaw>(law_).k_n);  // (6.6)
}

double Simulation::kinetic_energy() const {
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
  const auto& p = particles_;
  const auto& off = neighbors_.offsets();
  const auto& nb = neighbors_.neighbors();
  const auto& sh = neighbors_.shifts();
  const auto& hist = neighbors_.history();
  if (off.size() != p.size() + 1) return 0.0;
  std::array<Vec3, PeriodicImages::max_count> shifts{};
  neighbors_.shift_vectors(box_, shifts.data());
  double e = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::uint32_t k = off[i]; k < off[i + 1]; ++k) {
      const std::uint32_t j = nb[k];
      const double r = norm(p.position[j] + shifts[sh[k]] - p.position[i]);
      const double delta = r - p.radius[i] - p.radius[j];
      const Vec3 xi{hist[3 * k], hist[3 * k + 1], hist[3 * k + 2]};
      if (const auto* c = std::get_if<CohesiveLaw>(&law_)) {
        const auto& pp = pair_params_[k];
        if (c->cohesion) {
          e += normal_energy(pp, delta);
        } else if (delta < 0.0) {
          e += 0.5 * pp.k_n * delta * delta;
        }
        e += 0.5 * pp.k_t * dot(xi, xi);
      } else {
        const auto& h = std::get<HookeLaw>(law_);
        if (delta < 0.0) e += 0.5 * h.k_n * delta * delta;
        e += 0.5 * h.k_t * dot(xi, xi);
      }
    }
  return e;
}

Vec3 Simulation::momentum() const {
  Vec3 m{};
  for (std::size_t i = 0; i < particles_.size(); ++i) m += particles_.mass[i] * particles_.velocity[i];
  return m;
}

}  // namespace wearscale::dem
