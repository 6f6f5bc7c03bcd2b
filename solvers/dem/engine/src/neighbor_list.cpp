#include "wearscale/dem/neighbor_list.hpp"

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <fmt/format.h>
#include <omp.h>
#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

namespace {
// From this many particles the list is built on all threads.
constexpr std::size_t parallel_build = 8192;

// The distance test of the slots b = first + k (k < len ≤ 64) of a run, in
// single precision against the exact test |x_b + xs| < r_i + r_b + range:
// bit k of `sure` where the float copies' errors cannot change its outcome
// and it holds, of `maybe` where it holds or they might change it (a band a
// few 2⁻²⁰ wide about the reach, where the exact test decides). `reach_lo`
// and `reach_hi` are r_i + range less and plus twice those errors. A
// non-finite position is a `maybe` (the exact test keeps it, for the step's
// checks to catch). The arrays are in the grid's cell order and readable
// three slots past their ends (padding).
struct RunMasks {
  std::uint64_t maybe = 0, sure = 0;
};
RunMasks distance_test(const float* __restrict sx, const float* __restrict sy, const float* __restrict sz,
                       const float* __restrict sr, std::uint32_t first, std::uint32_t len, float xs_x, float xs_y,
                       float xs_z, float reach_lo, float reach_hi) {
  constexpr float narrow = 1.0f - 0x1p-18f, widen = 1.0f + 0x1p-18f;  // the float sums' own roundings, with room
  RunMasks m;
#if defined(__SSE2__)
  // Four slots a vector, each comparison's signs taken as four mask bits.
  const __m128 vx = _mm_set1_ps(xs_x), vy = _mm_set1_ps(xs_y), vz = _mm_set1_ps(xs_z);
  const __m128 lo_i = _mm_set1_ps(reach_lo), hi_i = _mm_set1_ps(reach_hi);
  const __m128 vn = _mm_set1_ps(narrow), vw = _mm_set1_ps(widen), zero = _mm_setzero_ps();
  for (std::uint32_t k = 0; k < len; k += 4) {
    const std::uint32_t b = first + k;
    const __m128 dx = _mm_add_ps(_mm_loadu_ps(sx + b), vx), dy = _mm_add_ps(_mm_loadu_ps(sy + b), vy),
                 dz = _mm_add_ps(_mm_loadu_ps(sz + b), vz);
    const __m128 d2 = _mm_add_ps(_mm_add_ps(_mm_mul_ps(dx, dx), _mm_mul_ps(dy, dy)), _mm_mul_ps(dz, dz));
    const __m128 r = _mm_loadu_ps(sr + b);
    const __m128 lo = _mm_max_ps(_mm_add_ps(lo_i, r), zero), hi = _mm_add_ps(hi_i, r);
    const auto in = static_cast<unsigned>(_mm_movemask_ps(_mm_cmplt_ps(d2, _mm_mul_ps(_mm_mul_ps(lo, lo), vn))));
    const auto out = static_cast<unsigned>(_mm_movemask_ps(_mm_cmpge_ps(d2, _mm_mul_ps(_mm_mul_ps(hi, hi), vw))));
    m.sure |= static_cast<std::uint64_t>(in) << k;
    m.maybe |= static_cast<std::uint64_t>(~out & 0xFu) << k;
  }
  const std::uint64_t valid = len >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << len) - 1;
  m.sure &= valid;
  m.maybe &= valid;
#else
  for (std::uint32_t k = 0; k < len; ++k) {
    const std::uint32_t b = first + k;
    const float dx = sx[b] + xs_x, dy = sy[b] + xs_y, dz = sz[b] + xs_z;
    const float d2 = dx * dx + dy * dy + dz * dz;
    const float lo = std::max(reach_lo + sr[b], 0.0f), hi = reach_hi + sr[b];
    m.sure |= static_cast<std::uint64_t>(d2 < lo * lo * narrow) << k;
    m.maybe |= static_cast<std::uint64_t>(!(d2 >= hi * hi * widen)) << k;
  }
#endif
  return m;
}

// The candidates js[k] the float test kept (bits of m.maybe): those not sure
// tested exactly, as one at a time (|x_j + xs| < r_i + r_j + range), none of
// home particle i's own wall; the pairs appended to the home stream (nb,
// sh) when j ≥ i, else to the other pairs as (j, i, the mirrored image).
// The work is per kept candidate, the branches on the masks' bits. The
// counts are locals here: a byte store may alias any memory.
template <class Pair>
void append_kept(std::uint32_t i, std::uint8_t image, std::uint8_t mirrored, const Vec3& xs, double range,
                 const std::uint32_t* __restrict js, RunMasks m, const Vec3* __restrict x,
                 const double* __restrict radius, const std::int16_t* __restrict wall, std::uint32_t* __restrict nb,
                 std::uint8_t* __restrict sh, Pair* __restrict other, std::size_t& pairs_io, std::size_t& others_io) {
  std::size_t pairs = pairs_io, others = others_io;
  const double ri = radius[i];
  const std::int16_t wi = wall[i];
  const bool rigid = wi != no_wall;  // rigid within a wall: its own particles are skipped
  for (std::uint64_t kept = m.maybe; kept != 0; kept &= kept - 1) {
    const int k = std::countr_zero(kept);
    const std::uint32_t j = js[k];
    if (!((m.sure >> k) & 1)) {
      const Vec3 d = x[j] + xs;
      const double reach_ij = ri + radius[j] + range;
      if (dot(d, d) >= reach_ij * reach_ij) continue;
    }
    if (rigid && wall[j] == wi) continue;
    if (i <= j) {  // i is the home particle: its visits come together
      nb[pairs] = j;
      sh[pairs++] = image;
    } else {
      other[others++] = {j, i, mirrored};
    }
  }
  pairs_io = pairs;
  others_io = others;
}

// Spare capacity of the history array (untouched pages, so not resident):
// the next builds' histories move within it instead of into a new array.
std::size_t with_slack(std::size_t doubles) { return doubles + doubles / 8 + 64; }
}  // namespace

void NeighborList::clear() {
  offset_.clear();
  neighbor_.clear();
  shift_.clear();
  history_.clear();
  built_at_.clear();
  built_image_.clear();
}

void NeighborList::build(const Particles& p, const Box& box, double reach, double skin, int history_size) {
  const std::size_t n = p.size();
  const bool carry = built_image_.size() == n && !offset_.empty() && history_size == history_size_;
  history_size_ = history_size;
  // The previous list's pairs stay for the carry-over; its histories stay
  // in history_ and move in place to their new slots (carry_history). The
  // arrays of the list before that are reused for the new one.
  old_offset_.swap(offset_);
  old_neighbor_.swap(neighbor_);
  old_shift_.swap(shift_);
  old_several_images_ = several_images_;
  if (!carry) {
    old_offset_.clear();
    history_.clear();
  }
  old_images_ = images_;
  half_skin_ = 0.5 * skin;
  ++builds_;

  double max_radius = 0.0;
  for (double r : p.radius) max_radius = std::max(max_radius, r);
  const double range = reach + skin;  // beyond r_i + r_j
  const double cut = 2.0 * max_radius + range;
  for (std::size_t a = 0; a < 3; ++a) {
    const double l = box.hi[static_cast<int>(a)] - box.lo[static_cast<int>(a)];
    if (box.periodic[a] && n > 0 && l < 2.0 * max_radius)
      throw InputError(fmt::format(
          "DEM box: the periodic length along {} is {:.6g}, shorter than the largest particle diameter {:.6g}: a "
          "particle would overlap its own image. Allowed: periodic lengths ≥ {:.6g}",
          "xyz"[a], l, 2.0 * max_radius, 2.0 * max_radius));
  }
  const int threads = n >= parallel_build ? std::max(1, omp_get_max_threads()) : 1;
  grid_.build(p.position, box, cut, threads);
  images_ = grid_.images();
  search(p, box, range, max_radius, threads);
  sort_rows(threads);
  if (carry)
    carry_history(p, box, threads);
  else {
    const std::size_t size = static_cast<std::size_t>(history_size_) * neighbor_.size();
    if (size > history_.capacity()) history_.reserve(with_slack(size));
    history_.assign(size, 0.0);
  }
  if (keep_positions_)
    built_at_.resize(n);
  else
    std::vector<Vec3>().swap(built_at_);
  built_image_.resize(n);
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) {
    if (keep_positions_) built_at_[i] = p.position[i];
    built_image_[i] = image_low_bytes(p.image[i]);
  }
}

// One walk over the cells, split over the threads by runs of cell layers
// holding about equal numbers of particles (CellGrid::layer_range). A pair
// belongs to the row of its lower index; the home particle's pairs with
// higher indices (most pairs, when particles are numbered along the cells)
// are kept as a stream of neighbours with a count per home particle (5 bytes
// a pair), the others as (row, neighbour, image) — there is no buffer of
// every candidate (12 bytes a pair). Then the rows' offsets, and each
// thread copies its stream to the front of its home particles' rows and
// its other pairs to the back of theirs (atomic cursors when threads share
// a row). The rows are sorted afterwards, so the list is the same bits on
// any thread count.
void NeighborList::search(const Particles& p, const Box& box, double range, double max_radius, int threads) {
  const std::size_t n = p.size();
  if (grid_.half_stencil()) {
    // The radii in the grid's cell order, beside its positions, in single
    // precision (the runs' first test; its rounding is allowed for).
    sorted_radius_.resize(n + 3);
    const std::span<const std::uint32_t> order = grid_.order();
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t b = 0; b < n; ++b) sorted_radius_[b] = static_cast<float>(p.radius[order[b]]);
    std::fill_n(sorted_radius_.begin() + static_cast<std::ptrdiff_t>(n), 3, 0.0f);  // padding
  }
  threads = std::max(1, std::min(threads, grid_.layers()));
  streams_.resize(static_cast<std::size_t>(threads));
  // Split by the threads the team has (fewer than asked in a nested region).
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num(), team = omp_get_num_threads();
    Stream& out = streams_[static_cast<std::size_t>(t)];
    out.pairs = out.homes = out.others = 0;
    const auto [z_begin, z_end] = grid_.layer_range(t, team);  // about equal particle counts
    // Room for a dense packing's pairs from the start: a vector that grows
    // leaves its old blocks resident in the thread's heap (untouched room
    // is not). The vectors' sizes only grow, to the most a build wrote.
    const std::size_t share = n / static_cast<std::size_t>(team) + 64;
    out.neighbor.reserve(8 * share);
    out.shift.reserve(8 * share);
    out.home.reserve(share);
    out.other.reserve(2 * share);
    auto room = [](auto& v, std::size_t size) {
      if (v.size() < size) v.resize(size);
    };
    const double* radius = p.radius.data();
    const std::int16_t* wall = p.wall.data();
    // Candidates js[0..len) of home particle i met through image s at
    // x_j + xs, the bits of m.maybe kept, those not in m.sure tested exactly.
    auto take = [&](std::uint32_t i, std::uint8_t s, const Vec3& xs, const std::uint32_t* js, RunMasks m,
                    std::size_t len) {
      room(out.neighbor, out.pairs + len);
      room(out.shift, out.pairs + len);
      room(out.other, out.others + len);
      const std::size_t pairs_before = out.pairs;
      append_kept(i, s, images_.mirrored(s), xs, range, js, m, p.position.data(), radius, wall,
                  out.neighbor.data(), out.shift.data(), out.other.data(), out.pairs, out.others);
      if (out.pairs == pairs_before) return;
      if (out.homes == 0 || out.home[out.homes - 1].i != i) {
        room(out.home, out.homes + 1);
        out.home[out.homes++] = {i, 0};
      }
      out.home[out.homes - 1].pairs += static_cast<std::uint32_t>(out.pairs - pairs_before);
    };
    if (grid_.half_stencil()) {
      // The distance test over a run of slots as arrays (the positions and
      // radii in cell order), then the kept ones appended.
      const std::uint32_t* order = grid_.order().data();
      const float* sx = grid_.sorted_positions(0).data();
      const float* sy = grid_.sorted_positions(1).data();
      const float* sz = grid_.sorted_positions(2).data();
      const float* sr = sorted_radius_.data();
      // The float copies' errors: the separation's per component (√3 of it
      // on its length, here 2), the radii's rounding to nearest.
      const double slack = 2.0 * grid_.sorted_position_error() + std::ldexp(max_radius, -22);
      constexpr std::uint32_t most = 64;  // slots a mask holds
      grid_.for_each_run(
          p.position,
          [&](std::uint32_t i, std::uint8_t s, const Vec3& xs, std::uint32_t begin, std::uint32_t end) {
            const auto reach_lo = static_cast<float>((radius[i] + range - slack) * (1.0 - 0x1p-20));
            const auto reach_hi = static_cast<float>((radius[i] + range + slack) * (1.0 + 0x1p-20));
            for (std::uint32_t b0 = begin; b0 < end; b0 += most) {
              const std::uint32_t len = std::min(most, end - b0);
              const RunMasks m = distance_test(sx, sy, sz, sr, b0, len, static_cast<float>(xs.x),
                                               static_cast<float>(xs.y), static_cast<float>(xs.z), reach_lo, reach_hi);
              take(i, s, xs, order + b0, m, len);
            }
          },
          z_begin, z_end);
    } else {  // a thin periodic cell: the candidates one by one, tested exactly
      std::array<Vec3, PeriodicImages::max_count> shift{};
      images_.vectors(box, shift.data());
      grid_.for_each_candidate(
          p.position,
          [&](std::uint32_t i, std::uint32_t j, std::uint8_t s, const Vec3&) {
            // d = x_j + xs as the grid's; the exact test decides
            take(i, s, shift[s] - p.position[i], &j, RunMasks{1, 0}, 1);
          },
          z_begin, z_end);
    }
  }
  // The rows' counts: each home particle in one stream; the other pairs from any.
  auto& count_buffer = grid_.scratch();  // free once the grid is built
  count_buffer.assign(n + 1, 0);
  std::uint32_t* count = count_buffer.data();
  const bool shared = threads > 1;
  const auto streams = static_cast<std::ptrdiff_t>(streams_.size());
#pragma omp parallel num_threads(threads)
  {
#pragma omp for schedule(static, 1)
    for (std::ptrdiff_t t = 0; t < streams; ++t)
      for (const auto& h : streams_[static_cast<std::size_t>(t)].homes_found()) count[h.i] += h.pairs;
#pragma omp for schedule(static, 1)
    for (std::ptrdiff_t t = 0; t < streams; ++t)
      for (const auto& c : streams_[static_cast<std::size_t>(t)].others_found()) {
        if (shared)
          std::atomic_ref<std::uint32_t>(count[c.i]).fetch_add(1, std::memory_order_relaxed);
        else
          ++count[c.i];
      }
  }
  offset_.resize(n + 1);
  offset_[0] = 0;
  for (std::size_t i = 0; i < n; ++i) offset_[i + 1] = offset_[i] + count[i];
  const std::size_t total = offset_[n];
  neighbor_.resize(total);
  shift_.resize(total);
  std::copy(offset_.begin() + 1, offset_.end(), count_buffer.begin());  // each row's back cursor
  std::uint32_t* nb = neighbor_.data();
  std::uint8_t* sh = shift_.data();
#pragma omp parallel for schedule(static, 1) num_threads(threads)
  for (std::ptrdiff_t t = 0; t < streams; ++t) {
    const Stream& in = streams_[static_cast<std::size_t>(t)];
    std::size_t from = 0;
    for (const auto& h : in.homes_found()) {
      std::copy_n(in.neighbor.begin() + static_cast<std::ptrdiff_t>(from), h.pairs, nb + offset_[h.i]);
      std::copy_n(in.shift.begin() + static_cast<std::ptrdiff_t>(from), h.pairs, sh + offset_[h.i]);
      from += h.pairs;
    }
    for (const auto& c : in.others_found()) {
      const std::uint32_t k =
          (shared ? std::atomic_ref<std::uint32_t>(count[c.i]).fetch_sub(1, std::memory_order_relaxed) : count[c.i]--) -
          1;
      nb[k] = c.j;
      sh[k] = c.shift;
    }
  }
}

void NeighborList::sort_rows(int threads) {
  const std::size_t n = offset_.empty() ? 0 : offset_.size() - 1;
  // Each particle's neighbours in increasing (index, image): memory order,
  // and the merge with the previous list in the carry-over.
  auto before = [&](std::uint32_t a, std::uint8_t sa, std::uint32_t b, std::uint8_t sb) {
    return a < b || (a == b && sa < sb);
  };
  bool several = false;
#pragma omp parallel for schedule(static) reduction(|| : several) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t b = offset_[i], e = offset_[i + 1];
    for (std::uint32_t k = b + 1; k < e; ++k) {
      const std::uint32_t j = neighbor_[k];
      const std::uint8_t s = shift_[k];
      std::uint32_t m = k;
      while (m > b && before(j, s, neighbor_[m - 1], shift_[m - 1])) {
        neighbor_[m] = neighbor_[m - 1];
        shift_[m] = shift_[m - 1];
        --m;
      }
      neighbor_[m] = j;
      shift_[m] = s;
    }
    for (std::uint32_t k = b + 1; k < e; ++k) several = several || neighbor_[k] == neighbor_[k - 1];
  }
  several_images_ = several;
}

// The histories of the previous build, in history_ at the old list's slots,
// moved to the slots of the same contacts in the new list; every other pair
// starts afresh. Rows keep their order and each row's contacts keep theirs,
// so a history only moves within its row's drift: the moves towards lower
// slots go in increasing order, then those towards higher ones (and the
// fresh zeros) in decreasing order, and no history is overwritten before it
// has moved — in place, without a copy of the old histories (which would
// be 24 bytes a pair at the peak of the build). Over threads the rows are
// cut into chunks; where a chunk's old slots overlap another chunk's new
// ones (the drift at its ends), those few histories are saved first.
void NeighborList::carry_history(const Particles& p, const Box& box, int threads) {
  const std::size_t n = p.size();
  const auto stride = static_cast<std::size_t>(history_size_);
  const std::size_t old_pairs = old_neighbor_.size(), new_pairs = neighbor_.size();
  // A contact is the pair and the image of j met by i in unwrapped terms:
  // x_j + s L − x_i with X = x + image L is X_j − X_i + (s − image_j + image_i) L,
  // so its shift changes by the periods j and i were wrapped by since the
  // last build, Δimage_j − Δimage_i.
  auto wrapped = [&](std::size_t i) {
    const auto now = image_low_bytes(p.image[i]);
    std::array<int, 3> d{};
    for (std::size_t a = 0; a < 3; ++a)  // modulo 256, then as a signed byte: |wraps| < max_wraps
      d[a] = static_cast<std::int8_t>(static_cast<std::uint8_t>(now[a] - built_image_[i][a]));
    return d;
  };
  // The carry-over's two flags a particle, bytes in the grid's scratch
  // (free after the search; ≥ n + 1 words): rewrapped[i], particle i was
  // wrapped since the last build; moves_up[i], row i has fresh pairs or
  // histories to move to higher slots.
  auto& flag_buffer = grid_.scratch();
  if (flag_buffer.size() * sizeof(std::uint32_t) < 2 * n) flag_buffer.resize((2 * n + 3) / 4);
  std::uint8_t* const rewrapped = reinterpret_cast<std::uint8_t*>(flag_buffer.data());  // a byte view: allowed
  std::uint8_t* const moves_up = rewrapped + n;
  // Which particles were wrapped since (few, in ten steps): the pairs of
  // two that were not keep their images' indices without a look at either.
#pragma omp parallel for schedule(static) num_threads(threads)
  for (std::size_t i = 0; i < n; ++i) {
    const auto now = image_low_bytes(p.image[i]);
    const auto& then = built_image_[i];
    rewrapped[i] = now[0] != then[0] || now[1] != then[1] || now[2] != then[2];
  }
  const bool same_images = old_images_ == images_;
  std::array<Vec3, PeriodicImages::max_count> shift_vector{};
  if (touching_only_) images_.vectors(box, shift_vector.data());
  // visit(k, b) for each pair k of row i whose contact was old pair b, in
  // increasing k.
  auto match_row = [&](std::size_t i, auto&& visit) {
    const bool i_wrapped = rewrapped[i] != 0;
    const std::array<int, 3> di = i_wrapped ? wrapped(i) : std::array<int, 3>{};
    std::uint32_t a = old_offset_[i];
    const std::uint32_t a_end = old_offset_[i + 1];
    for (std::uint32_t k = offset_[i]; k < offset_[i + 1] && a < a_end; ++k) {
      const std::uint32_t j = neighbor_[k];
      while (a < a_end && old_neighbor_[a] < j) ++a;
      if (a == a_end || old_neighbor_[a] != j) continue;  // a fresh pair
      const bool either_wrapped = i_wrapped || rewrapped[j] != 0;
      const std::array<int, 3> dj = either_wrapped ? wrapped(j) : di;
      const bool moved = either_wrapped && di != dj;
      // The old contacts of (i, j), one per image; the one that became this image.
      for (std::uint32_t b = a; b < a_end && old_neighbor_[b] == j; ++b) {
        int now = old_shift_[b];
        if (moved || !same_images) {
          std::array<int, 3> s = old_images_.shift(old_shift_[b]);
          for (std::size_t c = 0; c < 3; ++c) s[c] += dj[c] - di[c];
          now = images_.find(s);
        }
        if (now != shift_[k]) continue;
        if (touching_only_) {
          const Vec3 d = p.position[j] + shift_vector[shift_[k]] - p.position[i];
          const double contact = p.radius[i] + p.radius[j];
          if (!(dot(d, d) < contact * contact)) break;  // not touching: starts afresh
        }
        visit(k, b);
        break;
      }
    }
  };
  // In place needs each row's matches in increasing old slot. They are when
  // no row meets a neighbour through several images (the rows are sorted by
  // neighbour); otherwise checked (the images' order may have changed with
  // the image table), and when not, the moves go through a copy of the old
  // histories.
  bool ordered = true;
#pragma omp parallel for schedule(static) reduction(&& : ordered) num_threads(threads) \
    if (several_images_ || old_several_images_)
  for (std::size_t i = 0; i < (several_images_ || old_several_images_ ? n : 0); ++i) {
    std::int64_t last = -1;
    match_row(i, [&](std::uint32_t, std::uint32_t b) {
      ordered = ordered && static_cast<std::int64_t>(b) > last;
      last = b;
    });
  }
  if (!ordered) {
    const std::vector<double> old(history_.begin(), history_.begin() + static_cast<std::ptrdiff_t>(stride * old_pairs));
    history_.assign(stride * new_pairs, 0.0);
#pragma omp parallel for schedule(static) num_threads(threads)
    for (std::size_t i = 0; i < n; ++i)
      match_row(i, [&](std::uint32_t k, std::uint32_t b) {
        std::copy_n(old.begin() + static_cast<std::ptrdiff_t>(stride * b), stride,
                    history_.begin() + static_cast<std::ptrdiff_t>(stride * k));
      });
    return;
  }
  const std::size_t size = stride * std::max(old_pairs, new_pairs);
  if (size > history_.capacity()) history_.reserve(with_slack(size));
  history_.resize(size);
  // Chunks of rows, and the windows of each chunk's old slots that other
  // chunks write to: [oo[R_t], no[R_t]) when the list grew before R_t,
  // [no[R_t+1], oo[R_t+1]) when it shrank before R_t+1.
  const auto& oo = old_offset_;
  const auto& no = offset_;
  std::size_t chunks = static_cast<std::size_t>(threads);
  auto drift = [&](std::size_t r) {
    return static_cast<std::size_t>(std::abs(static_cast<std::int64_t>(no[r]) - static_cast<std::int64_t>(oo[r])));
  };
  std::size_t saved = 0;
  for (std::size_t t = 1; t < chunks; ++t) saved += drift(n * t / chunks);
  if (saved > new_pairs / 8 + 1024) chunks = 1;  // the list changed a lot: one chunk, nothing saved
  double* h = history_.data();
  struct Chunk {
    std::size_t r0, r1, lo_begin, lo_end, hi_begin, hi_end;
    std::vector<double> lo, hi;  // the saved windows
  };
  std::vector<Chunk> part(chunks);
  for (std::size_t t = 0; t < chunks; ++t) {
    Chunk& c = part[t];
    c.r0 = n * t / chunks;
    c.r1 = n * (t + 1) / chunks;
    c.lo_begin = oo[c.r0];
    c.hi_end = oo[c.r1];
    c.lo_end = t > 0 ? std::clamp<std::size_t>(no[c.r0], c.lo_begin, c.hi_end) : c.lo_begin;
    c.hi_begin = t + 1 < chunks ? std::clamp<std::size_t>(no[c.r1], c.lo_end, c.hi_end) : c.hi_end;
    c.lo.assign(h + stride * c.lo_begin, h + stride * c.lo_end);
    c.hi.assign(h + stride * c.hi_begin, h + stride * c.hi_end);
  }
#pragma omp parallel for schedule(static, 1) num_threads(static_cast<int>(chunks))
  for (std::size_t t = 0; t < chunks; ++t) {
    const Chunk& c = part[t];
    const std::size_t r0 = c.r0, r1 = c.r1;
    auto source = [&](std::size_t b) -> const double* {
      if (b < c.lo_end) return c.lo.data() + stride * (b - c.lo_begin);
      if (b >= c.hi_begin) return c.hi.data() + stride * (b - c.hi_begin);
      return h + stride * b;
    };
    // Towards lower slots, in increasing order; the rows left with work
    // for the second pass marked.
    for (std::size_t i = r0; i < r1; ++i) {
      std::uint32_t matched = 0;
      bool up = false;
      match_row(i, [&](std::uint32_t k, std::uint32_t b) {
        ++matched;
        if (b > k) std::copy_n(source(b), stride, h + stride * k);
        up = up || b < k;
      });
      moves_up[i] = up || matched != no[i + 1] - no[i];
    }
    // Towards higher slots and the fresh pairs' zeros, in decreasing order.
    std::vector<std::int64_t> from;
    for (std::size_t i = r1; i-- > r0;) {
      if (moves_up[i] == 0) continue;
      const std::uint32_t k0 = no[i], k1 = no[i + 1];
      from.assign(k1 - k0, -1);
      match_row(i, [&](std::uint32_t k, std::uint32_t b) { from[k - k0] = b; });
      for (std::uint32_t k = k1; k-- > k0;) {
        const std::int64_t b = from[k - k0];
        if (b < 0)
          std::fill_n(h + stride * k, stride, 0.0);
        else if (static_cast<std::size_t>(b) < k)
          std::copy_n(source(static_cast<std::size_t>(b)), stride, h + stride * k);
      }
    }
  }
  history_.resize(stride * new_pairs);
}

// Pairs placed row by row of the new numbering (a counting sort on the
// lower new index, the old list's order within a row), each row then
// sorted by (neighbour, image) as sort_rows() does, carrying the old slot
// of each pair; the histories are then permuted in place along the cycles
// of that permutation (no second history array: 24 bytes a pair).
void NeighborList::renumber(std::span<const std::uint32_t> new_index, const std::function<void(double*)>& reverse) {
  const std::size_t n = new_index.size();
  auto follow = [&](auto& per_particle) {  // new[new_index[i]] = old[i]
    if (per_particle.size() != n) return;
    auto old = per_particle;
    for (std::size_t i = 0; i < n; ++i) per_particle[new_index[i]] = old[i];
  };
  follow(built_at_);
  follow(built_image_);
  if (offset_.size() != n + 1) return;  // no list yet (or of another system): the next build starts afresh
  const auto stride = static_cast<std::size_t>(history_size_);
  const std::size_t pairs = neighbor_.size();
  // The new rows' counts, then their offsets (in the scratch of the old list).
  old_offset_.assign(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i)
    for (std::uint32_t k = offset_[i]; k < offset_[i + 1]; ++k)
      ++old_offset_[std::min(new_index[i], new_index[neighbor_[k]]) + 1];
  for (std::size_t i = 0; i < n; ++i) old_offset_[i + 1] += old_offset_[i];
  old_neighbor_.resize(pairs);
  old_shift_.resize(pairs);
  renumber_source_.resize(pairs);
  {
    std::vector<std::uint32_t> cursor(old_offset_.begin(), old_offset_.end() - 1);
    for (std::size_t i = 0; i < n; ++i)
      for (std::uint32_t k = offset_[i]; k < offset_[i + 1]; ++k) {
        const std::uint32_t a = new_index[i], b = new_index[neighbor_[k]];
        const bool swapped = b < a;
        const std::uint32_t m = cursor[swapped ? b : a]++;
        old_neighbor_[m] = swapped ? a : b;
        old_shift_[m] = swapped ? images_.mirrored(shift_[k]) : shift_[k];
        renumber_source_[m] = k;
        if (swapped && stride > 0) reverse(history_.data() + stride * k);
      }
  }
  // Each row by (neighbour, image), the source slots alongside.
  for (std::size_t r = 0; r < n; ++r) {
    const std::uint32_t b = old_offset_[r], e = old_offset_[r + 1];
    for (std::uint32_t k = b + 1; k < e; ++k) {
      const std::uint32_t j = old_neighbor_[k], src = renumber_source_[k];
      const std::uint8_t s = old_shift_[k];
      std::uint32_t m = k;
      while (m > b && (j < old_neighbor_[m - 1] || (j == old_neighbor_[m - 1] && s < old_shift_[m - 1]))) {
        old_neighbor_[m] = old_neighbor_[m - 1];
        old_shift_[m] = old_shift_[m - 1];
        renumber_source_[m] = renumber_source_[m - 1];
        --m;
      }
      old_neighbor_[m] = j;
      old_shift_[m] = s;
      renumber_source_[m] = src;
    }
  }
  // history(new m) = history(old source[m]), cycle by cycle; a slot done is
  // marked as its own source.
  if (stride > 0) {
    double* h = history_.data();
    std::vector<double> held(stride);
    for (std::size_t start = 0; start < pairs; ++start) {
      if (renumber_source_[start] == start) continue;
      std::copy_n(h + stride * start, stride, held.begin());
      std::size_t at = start;
      for (;;) {
        const std::size_t from = renumber_source_[at];
        renumber_source_[at] = static_cast<std::uint32_t>(at);
        if (from == start) {
          std::copy_n(held.begin(), stride, h + stride * at);
          break;
        }
        std::copy_n(h + stride * from, stride, h + stride * at);
        at = from;
      }
    }
  }
  offset_.swap(old_offset_);
  neighbor_.swap(old_neighbor_);
  shift_.swap(old_shift_);
}

bool NeighborList::moved_beyond_half_skin(const Particles& p) const {
  if (built_at_.size() != p.size()) return true;
  const double limit = half_skin_ * half_skin_;
  const std::size_t n = p.size();
  bool moved = false;
#pragma omp parallel for reduction(|| : moved) schedule(static) if (n > 20000)
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = p.position[i] - built_at_[i];
    moved = moved || dot(d, d) > limit;
  }
  return moved;
}

}  // namespace wearscale::dem
