#pragma once
// The pair loop over a neighbour list, one template instantiated per contact
// law (in the law's own .cpp, from its add_pair_forces()), so that the law's
// pair force is inlined into a tight loop: no virtual call, no variant visit
// and no bounds check per pair. Simulation fills a PairLoop once per force
// evaluation. The pairs go through in batches: their kinematics gathered as
// structure of arrays, the law's force over the batch in one vectorised
// loop, then the sums in list order (the same bits as one pair at a time).
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <omp.h>
#include <type_traits>
#include <vector>

#include "wearscale/dem/contact_law.hpp"
#include "wearscale/dem/vec3.hpp"

// The batch kernel is also compiled for AVX-512 and AVX2 and picked at load
// time by the CPU (GCC's target_clones; the library's baseline is x86-64-v2).
// With -ffp-contract=off (solvers/dem/CMakeLists.txt) no multiply-add is
// fused, so every lane computes the baseline's bits.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__SANITIZE_ADDRESS__)
#define WEARSCALE_PAIR_KERNEL __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define WEARSCALE_PAIR_KERNEL
#endif
// The batch's lanes are independent (each pair its own history and outputs).
#if defined(__clang__)
#define WEARSCALE_INDEPENDENT_LANES _Pragma("clang loop vectorize(enable)")
#elif defined(__GNUC__)
#define WEARSCALE_INDEPENDENT_LANES _Pragma("GCC ivdep")
#else
#define WEARSCALE_INDEPENDENT_LANES
#endif

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
  /// The two-colour threaded loop's blocks of rows, block b from
  /// block_start[b] to block_start[b + 1] (blocks == 0: per-thread buffers).
  const std::size_t* block_start = nullptr;
  std::size_t blocks = 0;
  double dt = 0.0;
  bool advance = false;  // the step's evaluation: sliding histories move
};

namespace detail {

// ½ (d ⊗ f), symmetrised, into w (xx yy zz xy xz yz): the pair's share of
// the virial of each particle (also the LAMMPS pair styles' per-atom rows).
inline void add_outer(double* w, const Vec3& d, const Vec3& f) {
  w[0] += 0.5 * d.x * f.x;
  w[1] += 0.5 * d.y * f.y;
  w[2] += 0.5 * d.z * f.z;
  w[3] += 0.25 * (d.x * f.y + d.y * f.x);
  w[4] += 0.25 * (d.x * f.z + d.z * f.x);
  w[5] += 0.25 * (d.y * f.z + d.z * f.y);
}

// Pairs gathered at a time: the batch's arrays (20 doubles a pair) stay in
// the first-level cache.
inline constexpr std::size_t batch_pairs = 128;
// The largest history a law may declare as its fixed stride.
inline constexpr std::size_t max_fixed_history = 4;

// One batch of consecutive pairs of the list as structure of arrays: the
// gathered kinematics (PairState), and the force on i and the torque arm
// n × F_T the law's vectorised loop writes (also the LAMMPS pair styles'
// batch of list entries).
struct alignas(64) Batch {
  double dx[batch_pairs], dy[batch_pairs], dz[batch_pairs];
  double vx[batch_pairs], vy[batch_pairs], vz[batch_pairs];
  double wx[batch_pairs], wy[batch_pairs], wz[batch_pairs];
  double ri[batch_pairs], rj[batch_pairs], mi[batch_pairs], mj[batch_pairs];
  double fx[batch_pairs], fy[batch_pairs], fz[batch_pairs];
  double ax[batch_pairs], ay[batch_pairs], az[batch_pairs];
  // As wide as a double: GCC sizes the vectorised loop by its narrowest type,
  // and byte flags made it 64 pairs an iteration (spilling, long epilogues).
  std::uint64_t active[batch_pairs];
  double history[batch_pairs * max_fixed_history];  // the updated histories (fixed strides)
};

// The law on `m` gathered pairs from list pair k0 on, one lane a pair.
// `Stride` doubles of history a pair: the law reads a pair's history from
// the list and writes the updated one into the batch, copied back after the
// loop (distinct arrays: every store is unconditional, which vectorises).
// Stride 0: the list's runtime history_size, updated in place.
template <class Law, std::size_t Stride, bool Advance>
WEARSCALE_PAIR_KERNEL void batch_forces(const Law& law, Batch& b, std::size_t k0, std::size_t m, double* history,
                                        std::size_t stride, double dt) {
  static_assert(Stride <= max_fixed_history);
  const std::size_t h = Stride > 0 ? Stride : stride;
  const double* before = history + h * k0;
  double* after = Stride > 0 ? b.history : history + h * k0;
WEARSCALE_INDEPENDENT_LANES
  for (std::size_t l = 0; l < m; ++l) {
    const PairState s{{b.dx[l], b.dy[l], b.dz[l]}, {b.vx[l], b.vy[l], b.vz[l]}, {b.wx[l], b.wy[l], b.wz[l]},
                      b.ri[l], b.rj[l], b.mi[l], b.mj[l]};
    const PairForce pf = law.contact(k0 + l, s, before + h * l, after + h * l, dt, Advance);
    const Vec3 arm = cross(pf.normal, pf.tangential);
    b.fx[l] = pf.force.x;
    b.fy[l] = pf.force.y;
    b.fz[l] = pf.force.z;
    b.ax[l] = arm.x;
    b.ay[l] = arm.y;
    b.az[l] = arm.z;
    b.active[l] = pf.active ? 1u : 0u;
  }
  if constexpr (Stride > 0) std::copy_n(b.history, Stride * m, history + Stride * k0);
}

// Rows [ib, ie) of the half list, batch by batch: the pairs' kinematics
// gathered into a Batch, the law's forces in one vectorised loop over it,
// then the sums in list order — the force on i summed locally and the
// opposite force scattered to each j, as a row-by-row loop would, so the
// sums are the same bits as one pair at a time.
template <class Law, bool Virial, std::size_t Stride, bool Advance>
void pair_rows(const Law& law, const PairLoop& a, std::size_t ib, std::size_t ie, Vec3* f, Vec3* tq,
               SymTensor* vir) {
  if (ib >= ie) return;
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
  Batch b;
  std::size_t gather_row = ib, sum_row = ib;
  Vec3 fi{}, ti{};
  const std::size_t k_end = off[ie];
  for (std::size_t k0 = off[ib];; k0 += batch_pairs) {
    const std::size_t k1 = std::min(k_end, k0 + batch_pairs);
    for (std::size_t k = k0; k < k1;) {
      while (off[gather_row + 1] <= k) ++gather_row;
      const std::size_t i = gather_row, end = std::min<std::size_t>(off[i + 1], k1);
      const Vec3 xi = x[i], vi = v[i], wi = w[i];
      const double ri = rad[i], mi = mass[i];
      for (; k < end; ++k) {
        const std::size_t l = k - k0, j = nb[k];
        const Vec3 d = x[j] + shift[sh[k]] - xi;
        const Vec3 vr = vi - v[j];
        const Vec3 ws = ri * wi + rad[j] * w[j];
        b.dx[l] = d.x, b.dy[l] = d.y, b.dz[l] = d.z;
        b.vx[l] = vr.x, b.vy[l] = vr.y, b.vz[l] = vr.z;
        b.wx[l] = ws.x, b.wy[l] = ws.y, b.wz[l] = ws.z;
        b.ri[l] = ri, b.rj[l] = rad[j], b.mi[l] = mi, b.mj[l] = mass[j];
      }
    }
    batch_forces<Law, Stride, Advance>(law, b, k0, k1 - k0, a.history, stride, a.dt);
    for (std::size_t k = k0; k < k1;) {
      while (off[sum_row + 1] <= k) {  // rows ended (or empty): their own sums
        f[sum_row] += fi;
        tq[sum_row] += ti;
        fi = ti = Vec3{};
        ++sum_row;
      }
      const std::size_t i = sum_row, end = std::min<std::size_t>(off[i + 1], k1);
      const double ri = rad[i];
      for (; k < end; ++k) {
        const std::size_t l = k - k0;
        if (b.active[l] == 0) continue;
        const std::size_t j = nb[k];
        const Vec3 force{b.fx[l], b.fy[l], b.fz[l]}, arm{b.ax[l], b.ay[l], b.az[l]};
        fi += force;
        f[j] -= force;
        ti += ri * arm;
        tq[j] += b.rj[l] * arm;
        if constexpr (Virial) {
          const Vec3 d{b.dx[l], b.dy[l], b.dz[l]};
          add_outer(vir[i].data(), d, force);
          add_outer(vir[j].data(), d, force);
        }
      }
    }
    if (k1 == k_end) break;
  }
  for (; sum_row < ie; ++sum_row) {
    f[sum_row] += fi;
    tq[sum_row] += ti;
    fi = ti = Vec3{};
  }
}

template <class Law, bool Virial, std::size_t Stride, bool Advance>
void pair_loop(const Law& law, PairLoop& a) {
  const std::size_t n = a.n;
  auto rows = [&](std::size_t ib, std::size_t ie, Vec3* f, Vec3* tq, SymTensor* vir) {
    pair_rows<Law, Virial, Stride, Advance>(law, a, ib, ie, f, tq, vir);
  };

  if (a.threads <= 1) {
    rows(0, n, a.force, a.torque, a.virial);
    return;
  }
  if (a.blocks > 0) {
    // Two colours of blocks of rows: every j of a row lies in the row's
    // block or the next (each block but the last spans at least the list's
    // largest j − i), so the blocks of one colour write to disjoint
    // particles and the threads share the force arrays without copies or
    // atomics; the colours are separated by the barrier at the end of each
    // `omp for`. The order of the sums is fixed by the blocks, not by the
    // threads (which thread takes a block does not matter): the same result
    // on any thread count ≥ 2. Each thread takes a contiguous run of each
    // colour's blocks (static schedule), so it works on the same stretch of
    // particles as in the integration's static loops and the neighbour
    // search's layers: the particles' cache lines stay with one core (taken
    // as they came free, 32 000 particles ran at 13.5-13.9 M particle-steps
    // per wall-second on two threads against 15.5-15.7 now).
    const std::size_t blocks = a.blocks;
    const std::size_t* start = a.block_start;
#pragma omp parallel num_threads(a.threads)
    for (std::size_t colour = 0; colour < 2; ++colour) {
      const std::size_t count = (blocks + 1 - colour) / 2;
#pragma omp for schedule(static)
      for (std::size_t c = 0; c < count; ++c) {
        const std::size_t b = colour + 2 * c;
        rows(start[b], start[b + 1], a.force, a.torque, a.virial);
      }
    }
    return;
  }
  // A list whose pairs reach far in index (an unordered sample): per-thread
  // buffers, then a reduction. Rows in chunks of 512, dealt round-robin.
  constexpr std::size_t chunk = 512;
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
#pragma omp for schedule(static, 1)
    for (std::size_t c = 0; c < (n + chunk - 1) / chunk; ++c) rows(c * chunk, std::min(n, (c + 1) * chunk), f, tq, vir);
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

template <class Law, bool Virial, std::size_t Stride>
void pair_loop(const Law& law, PairLoop& a) {
  if (a.advance)
    pair_loop<Law, Virial, Stride, true>(law, a);
  else
    pair_loop<Law, Virial, Stride, false>(law, a);
}

// A law that states its history size (`static constexpr int
// history_doubles`) gets a loop with that fixed stride, which vectorises;
// otherwise the list's runtime stride.
template <class Law, bool Virial>
void pair_loop(const Law& law, PairLoop& a) {
  if constexpr (requires { Law::history_doubles; }) {
    static_assert(Law::history_doubles > 0 && Law::history_doubles <= static_cast<int>(max_fixed_history));
    pair_loop<Law, Virial, static_cast<std::size_t>(Law::history_doubles)>(law, a);
  } else {
    pair_loop<Law, Virial, 0>(law, a);
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
