#include "wearscale/dem/neighbor_list.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <omp.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

namespace {
// From this many particles the list is built on all threads.
constexpr std::size_t parallel_build = 8192;
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
  const bool carry =
      built_at_.size() == n && built_image_.size() == n && !offset_.empty() && history_size == history_size_;
  history_size_ = history_size;
  if (carry) {
    old_offset_.swap(offset_);
    old_neighbor_.swap(neighbor_);
    old_shift_.swap(shift_);
    old_history_.swap(history_);
    old_images_ = images_;
  } else {
    old_offset_.clear();
  }
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
  grid_.build(p.position, box, cut);
  images_ = grid_.images();
  // The search split by cell layers over the threads, each into its own
  // candidates; the rows are sorted below, so the list is the same on any
  // number of threads.
  const int threads = n >= parallel_build ? std::max(1, std::min(omp_get_max_threads(), grid_.layers())) : 1;
  thread_candidates_.resize(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    const int t = omp_get_thread_num();
    auto& out = thread_candidates_[static_cast<std::size_t>(t)];
    out.clear();
    const int layers = grid_.layers();
    grid_.for_each_candidate(
        p.position,
        [&](std::uint32_t i, std::uint32_t j, std::uint8_t s, const Vec3& d) {
          if (p.wall[i] != no_wall && p.wall[i] == p.wall[j]) return;  // rigid within a wall
          const double reach_ij = p.radius[i] + p.radius[j] + range;
          if (dot(d, d) >= reach_ij * reach_ij) return;
          if (i <= j)
            out.push_back({i, j, s});
          else
            out.push_back({j, i, images_.mirrored(s)});
        },
        layers * t / threads, layers * (t + 1) / threads);
  }
  sort_and_keep_history(p, box);
  built_at_.assign(p.position.begin(), p.position.end());
  built_image_.assign(p.image.begin(), p.image.end());
}

void NeighborList::sort_and_keep_history(const Particles& p, const Box& box) {
  const std::size_t n = p.size();
  // Counting sort of the candidates by their lower index.
  count_.assign(n + 1, 0);
  std::size_t total = 0;
  for (const auto& part : thread_candidates_) {
    for (const auto& c : part) ++count_[c.i + 1];
    total += part.size();
  }
  offset_.resize(n + 1);
  offset_[0] = 0;
  for (std::size_t i = 0; i < n; ++i) offset_[i + 1] = offset_[i] + count_[i + 1];
  neighbor_.resize(total);
  shift_.resize(total);
  for (std::size_t i = 0; i < n; ++i) count_[i] = offset_[i];
  for (const auto& part : thread_candidates_)
    for (const auto& c : part) {
      const std::uint32_t k = count_[c.i]++;
      neighbor_[k] = c.j;
      shift_[k] = c.shift;
    }
  // Each particle's neighbours in increasing (index, image): memory order,
  // and the merge with the previous list below.
  auto before = [&](std::uint32_t a, std::uint8_t sa, std::uint32_t b, std::uint8_t sb) {
    return a < b || (a == b && sa < sb);
  };
#pragma omp parallel for schedule(static) if (n >= parallel_build)
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
  }
  const auto stride = static_cast<std::size_t>(history_size_);
  history_.assign(stride * neighbor_.size(), 0.0);
  if (old_offset_.size() != n + 1) return;
  // A contact is the pair and the image of j met by i in unwrapped terms:
  // x_j + s L − x_i with X = x + image L is X_j − X_i + (s − image_j + image_i) L,
  // so its shift changes by the periods j and i were wrapped by since the
  // last build, Δimage_j − Δimage_i.
  auto wrapped = [&](std::size_t i) {
    std::array<int, 3> d{};
    for (std::size_t a = 0; a < 3; ++a) d[a] = p.image[i][a] - built_image_[i][a];
    return d;
  };
  const bool same_images = old_images_ == images_;
  std::array<Vec3, PeriodicImages::max_count> shift_vector{};
  if (touching_only_) images_.vectors(box, shift_vector.data());
#pragma omp parallel for schedule(static) if (n >= parallel_build)
  for (std::size_t i = 0; i < n; ++i) {
    const std::array<int, 3> di = wrapped(i);
    std::uint32_t a = old_offset_[i];
    const std::uint32_t a_end = old_offset_[i + 1];
    for (std::uint32_t k = offset_[i]; k < offset_[i + 1] && a < a_end; ++k) {
      const std::uint32_t j = neighbor_[k];
      while (a < a_end && old_neighbor_[a] < j) ++a;
      const std::array<int, 3> dj = wrapped(j);
      const bool moved = di != dj;
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
        std::copy_n(old_history_.begin() + static_cast<std::ptrdiff_t>(stride * b), stride,
                    history_.begin() + static_cast<std::ptrdiff_t>(stride * k));
        break;
      }
    }
  }
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
