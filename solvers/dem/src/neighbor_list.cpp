#include "wearscale/dem/neighbor_list.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::dem {

namespace {

std::uint8_t shift_index(int sx, int sy, int sz) {
  return static_cast<std::uint8_t>((sx + 1) + 3 * (sy + 1) + 9 * (sz + 1));
}

// The opposite image: the shift of i seen from j.
std::uint8_t mirrored(std::uint8_t s) { return static_cast<std::uint8_t>(26 - s); }

}  // namespace

std::array<Vec3, 27> NeighborList::shift_vectors(const Box& box) {
  const Vec3 l = box.length();
  std::array<Vec3, 27> table{};
  for (int sz = -1; sz <= 1; ++sz)
    for (int sy = -1; sy <= 1; ++sy)
      for (int sx = -1; sx <= 1; ++sx)
        table[shift_index(sx, sy, sz)] = {sx * l.x, sy * l.y, sz * l.z};
  return table;
}

void NeighborList::clear() {
  offset_.clear();
  neighbor_.clear();
  shift_.clear();
  history_.clear();
  built_at_.clear();
}

void NeighborList::build(const Particles& p, const Box& box, double reach, double skin) {
  const std::size_t n = p.size();
  const bool carry = built_at_.size() == n && !offset_.empty();
  if (carry) {
    old_offset_.swap(offset_);
    old_neighbor_.swap(neighbor_);
    old_history_.swap(history_);
  } else {
    old_offset_.clear();
  }
  candidates_.clear();
  half_skin_ = 0.5 * skin;
  ++builds_;

  double max_radius = 0.0;
  for (double r : p.radius) max_radius = std::max(max_radius, r);
  const double range = reach + skin;  // beyond r_i + r_j
  const double cut = 2.0 * max_radius + range;

  // Cell grid: the box on periodic axes, the particles' extent on open ones.
  std::array<int, 3> cells{};
  Vec3 lo{}, size{};
  bool brute_force = n < 2;
  for (int a = 0; a < 3; ++a) {
    const auto ua = static_cast<std::size_t>(a);
    double l = 0.0;
    if (box.periodic[ua]) {
      lo[a] = box.lo[a];
      l = box.hi[a] - box.lo[a];
      if (l < 2.0 * cut)
        throw InputError(fmt::format(
            "DEM box: the periodic length along {} is {:.6g}, shorter than twice the neighbour "
            "cutoff 2 r_max + reach + skin = {:.6g}; a particle would meet two images of another. "
            "Allowed: periodic lengths ≥ {:.6g}",
            "xyz"[a], l, cut, 2.0 * cut));
    } else {
      double mn = 0.0, mx = 0.0;
      if (n > 0) {
        mn = mx = p.position[0][a];
        for (const auto& x : p.position) {
          mn = std::min(mn, x[a]);
          mx = std::max(mx, x[a]);
        }
      }
      lo[a] = mn;
      l = std::max(mx - mn, cut) * (1.0 + 1e-12);
    }
    cells[ua] = std::max(1, static_cast<int>(std::floor(l / cut)));
    if (box.periodic[ua] && cells[ua] < 3) brute_force = true;
    size[a] = l / cells[ua];
  }

  auto consider = [&](std::uint32_t i, std::uint32_t j, std::uint8_t s, const Vec3& d) {
    if (p.wall[i] != no_wall && p.wall[i] == p.wall[j]) return;  // rigid within a wall
    const double reach_ij = p.radius[i] + p.radius[j] + range;
    if (dot(d, d) >= reach_ij * reach_ij) return;
    if (i < j)
      candidates_.push_back({i, j, s});
    else
      candidates_.push_back({j, i, mirrored(s)});
  };

  if (brute_force) {
    const Vec3 l = box.length();
    for (std::uint32_t i = 0; i < n; ++i)
      for (std::uint32_t j = i + 1; j < n; ++j) {
        Vec3 d = p.position[j] - p.position[i];
        std::array<int, 3> s{0, 0, 0};
        for (int a = 0; a < 3; ++a) {
          if (!box.periodic[static_cast<std::size_t>(a)]) continue;
          s[static_cast<std::size_t>(a)] = -static_cast<int>(std::nearbyint(d[a] / l[a]));
          d[a] += s[static_cast<std::size_t>(a)] * l[a];
        }
        consider(i, j, shift_index(s[0], s[1], s[2]), d);
      }
  } else {
    const std::size_t ncell = static_cast<std::size_t>(cells[0]) * static_cast<std::size_t>(cells[1]) *
                              static_cast<std::size_t>(cells[2]);
    constexpr std::uint32_t none = 0xffffffffu;
    cell_head_.assign(ncell, none);
    cell_next_.resize(n);
    auto cell_of = [&](const Vec3& x, int a) {
      const auto ua = static_cast<std::size_t>(a);
      int c = static_cast<int>(std::floor((x[a] - lo[a]) / size[a]));
      return std::clamp(c, 0, cells[ua] - 1);
    };
    auto flat = [&](int cx, int cy, int cz) {
      return static_cast<std::size_t>(cx) +
             static_cast<std::size_t>(cells[0]) *
                 (static_cast<std::size_t>(cy) + static_cast<std::size_t>(cells[1]) * static_cast<std::size_t>(cz));
    };
    // Insert in reverse so that each cell's list runs in increasing index.
    for (std::size_t k = n; k-- > 0;) {
      const std::size_t c = flat(cell_of(p.position[k], 0), cell_of(p.position[k], 1), cell_of(p.position[k], 2));
      cell_next_[k] = cell_head_[c];
      cell_head_[c] = static_cast<std::uint32_t>(k);
    }
    const auto shifts = shift_vectors(box);
    // Half stencil: the cell itself and the 13 neighbours "after" it.
    static constexpr int stencil[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0},  {-1, -1, 1},
                                           {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1},  {1, 0, 1},
                                           {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};
    for (int cz = 0; cz < cells[2]; ++cz)
      for (int cy = 0; cy < cells[1]; ++cy)
        for (int cx = 0; cx < cells[0]; ++cx) {
          const std::size_t home = flat(cx, cy, cz);
          for (std::uint32_t i = cell_head_[home]; i != none; i = cell_next_[i]) {
            const Vec3 xi = p.position[i];
            for (std::uint32_t j = cell_next_[i]; j != none; j = cell_next_[j])
              consider(i, j, no_shift, p.position[j] - xi);
            for (const auto& o : stencil) {
              std::array<int, 3> c{cx + o[0], cy + o[1], cz + o[2]};
              std::array<int, 3> s{0, 0, 0};
              bool outside = false;
              for (std::size_t a = 0; a < 3; ++a) {
                if (c[a] >= 0 && c[a] < cells[a]) continue;
                if (!box.periodic[a]) {
                  outside = true;
                  break;
                }
                s[a] = c[a] < 0 ? -1 : 1;
                c[a] -= s[a] * cells[a];
              }
              if (outside) continue;
              const std::uint8_t sh = shift_index(s[0], s[1], s[2]);
              const Vec3 xs = shifts[sh] - xi;
              for (std::uint32_t j = cell_head_[flat(c[0], c[1], c[2])]; j != none; j = cell_next_[j])
                consider(i, j, sh, p.position[j] + xs);
            }
          }
        }
  }
  sort_and_keep_history(n);
  built_at_.assign(p.position.begin(), p.position.end());
}

void NeighborList::sort_and_keep_history(std::size_t n) {
  // Counting sort of the candidates by their lower index.
  count_.assign(n + 1, 0);
  for (const auto& c : candidates_) ++count_[c.i + 1];
  offset_.resize(n + 1);
  offset_[0] = 0;
  for (std::size_t i = 0; i < n; ++i) offset_[i + 1] = offset_[i] + count_[i + 1];
  neighbor_.resize(candidates_.size());
  shift_.resize(candidates_.size());
  for (std::size_t i = 0; i < n; ++i) count_[i] = offset_[i];
  for (const auto& c : candidates_) {
    const std::uint32_t k = count_[c.i]++;
    neighbor_[k] = c.j;
    shift_[k] = c.shift;
  }
  // Each particle's neighbours in increasing index: memory order, and the
  // merge with the previous list below.
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t b = offset_[i], e = offset_[i + 1];
    for (std::uint32_t k = b + 1; k < e; ++k) {
      const std::uint32_t j = neighbor_[k];
      const std::uint8_t s = shift_[k];
      std::uint32_t m = k;
      while (m > b && neighbor_[m - 1] > j) {
        neighbor_[m] = neighbor_[m - 1];
        shift_[m] = shift_[m - 1];
        --m;
      }
      neighbor_[m] = j;
      shift_[m] = s;
    }
  }
  history_.assign(3 * neighbor_.size(), 0.0);
  if (old_offset_.size() != n + 1) return;
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t a = old_offset_[i];
    const std::uint32_t a_end = old_offset_[i + 1];
    for (std::uint32_t k = offset_[i]; k < offset_[i + 1] && a < a_end; ++k) {
      while (a < a_end && old_neighbor_[a] < neighbor_[k]) ++a;
      if (a < a_end && old_neighbor_[a] == neighbor_[k]) {
        for (int c = 0; c < 3; ++c) history_[3 * k + static_cast<std::uint32_t>(c)] = old_history_[3 * a + static_cast<std::uint32_t>(c)];
        ++a;
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
