#pragma once
// The pair loop over a neighbour list, one template instantiated per contact
// law (in the law's own .cpp, from its add_pair_forces()), so that the law's
// pair force is inlined into a tight loop: no virtual call, no variant visit
// and no bounds check per pair. Simulation fills a PairLoop once per force
// evaluation.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <omp.h>
#include <type_traits>
#include <vector>

#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/vec3.hpp"

namespace wearscale::dem {

/// Symmetric 3×3 tensor as xx, yy, zz, xy, xz, yz.
using SymTensor = std::array<double, 6>;

/// The arrays of one force evaluation.
struct PairLoop {
  std::size_t n = 0;
  const std::uint32_t* offset = nullptr;    // pairs of i: [offset[i], offset[i+1])
  const std::uint32_t* neighbor = nullptr;  // j of pair k
  const std::uint8_t* image = nullptr;      // image index of pair k into `shift`
  const Vec3* shift = nullptr;              // image offsets
  double* history = nullptr;                // history_size per pair
  int history_size = 3;
  const Vec3* x = nullptr;
  const Vec3* v = nullptr;
  const Vec3* w = nullptr;
  const double* radius = nullptr;
  const double* mass = nullptr;
  Vec3* force = nullptr;       // accumulated into (zeroed by the caller)
  Vec3* torque = nullptr;
  SymTensor* virial = nullptr;  // nullptr: not tracked
  // Per-thread buffers for threads 1..threads-1 (the caller sizes them).
  std::vector<std::vector<Vec3>>* thread_force = nullptr;
  std::vector<std::vector<Vec3>>* thread_torque = nullptr;
  std::vector<std::vector<SymTensor>>* thread_virial = nullptr;
  int threads = 1;
  /// Rows per block of the two-colour threaded loop (0: per-thread buffers).
  std::size_t block = 0;
  double dt = 0.0;
  bool advance = false;  // the step's evaluation: sliding histories move
};

namespace detail {

inline void add_outer(SymTensor& w, const Vec3& d, const Vec3& f) {
  // ½ (d ⊗ f), symmetrised: the pair's share of the virial of each particle.
  w[0] += 0.5 * d.x * f.x;
  w[1] += 0.5 * d.y * f.y;
  w[2] += 0.5 * d.z * f.z;
  w[3] += 0.25 * (d.x * f.y + d.y * f.x);
  w[4] += 0.25 * (d.x * f.z + d.z * f.x);
  w[5] += 0.25 * (d.y * f.z + d.z * f.y);
}

// `law.contact(k, state, history, dt, advance)` is the law's pair force.
template <class Law, bool Virial>
void pair_loop(const Law& law, PairLoop& a) {
  const std::size_t n = a.n;
  const std::uint32_t* off = a.offset;
  const std::uint32_t* nb = a.neighbor;
  const std::uint8_t* sh = a.image;
  const Vec3* shift = a.shift;
  const Vec3* x = a.x;
  const Vec3* v = a.v;
  const Vec3* w = a.w;
  const double* rad = a.radius;
  const double* mass = a.mass;
  const std::size_t stride = static_cast<std::size_t>(a.history_size);
  const double dt = a.dt;
  const bool advance = a.advance;

  // One row of the half list: i's pairs, the force on i summed locally and
  // the opposite force scattered to each j (j ≥ i).
  auto row = [&](std::size_t i, Vec3* f, Vec3* tq, SymTensor* vir) {
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
      const PairForce pf = law.contact(k, s, a.history + stride * k, dt, advance);
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
  };

  if (a.threads <= 1) {
    for (std::size_t i = 0; i < n; ++i) row(i, a.force, a.torque, a.virial);
    return;
  }
  if (a.block > 0) {
    // Two colours of blocks of `block` rows: every j of a row lies in the
    // row's block or the next (block ≥ the list's largest j − i), so the
    // blocks of one colour write to disjoint particles and the threads share
    // the force arrays without copies or atomics; the colours are separated
    // by the barrier at the end of each `omp for`. The order of the sums is
    // fixed by the blocks, not by the threads: the same result on any thread
    // count ≥ 2.
    const std::size_t block = a.block;
    const std::size_t blocks = (n + block - 1) / block;
#pragma omp parallel num_threads(a.threads)
    for (std::size_t colour = 0; colour < 2; ++colour) {
      const std::size_t count = (blocks + 1 - colour) / 2;
#pragma omp for schedule(static)
      for (std::size_t c = 0; c < count; ++c) {
        const std::size_t begin = (colour + 2 * c) * block, end = std::min(n, begin + block);
        for (std::size_t i = begin; i < end; ++i) row(i, a.force, a.torque, a.virial);
      }
    }
    return;
  }
  // A list whose pairs reach far in index (an unordered sample): per-thread
  // buffers, then a reduction.
#pragma omp parallel num_threads(a.threads)
  {
    const auto t = static_cast<std::size_t>(omp_get_thread_num());
    Vec3* f = t == 0 ? a.force : (*a.thread_force)[t].data();
    Vec3* tq = t == 0 ? a.torque : (*a.thread_torque)[t].data();
    SymTensor* vir = nullptr;
    if constexpr (Virial) vir = t == 0 ? a.virial : (*a.thread_virial)[t].data();
    if (t != 0) {
      std::fill_n(f, n, Vec3{});
      std::fill_n(tq, n, Vec3{});
      if constexpr (Virial) std::fill_n(vir, n, SymTensor{});
    }
#pragma omp for schedule(static, 512)
    for (std::size_t i = 0; i < n; ++i) row(i, f, tq, vir);
  }
  const auto threads = static_cast<std::size_t>(a.threads);
#pragma omp parallel for schedule(static) num_threads(a.threads)
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t t = 1; t < threads; ++t) {
      a.force[i] += (*a.thread_force)[t][i];
      a.torque[i] += (*a.thread_torque)[t][i];
      if constexpr (Virial)
        for (std::size_t c = 0; c < 6; ++c) a.virial[i][c] += (*a.thread_virial)[t][i][c];
    }
}

}  // namespace detail

/// Runs the pair loop of `law` (call it from the law's add_pair_forces()).
template <class Law>
void run_pair_loop(const Law& law, PairLoop& loop) {
  if (loop.virial != nullptr)
    detail::pair_loop<Law, true>(law, loop);
  else
    detail::pair_loop<Law, false>(law, loop);
}

}  // namespace wearscale::dem
