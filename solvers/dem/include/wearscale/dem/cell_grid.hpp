#pragma once
// A cell list for pair searches within a cutoff on periodic and open axes,
// which visits every periodic image of every pair whose cells are within
// reach once. When each periodic axis holds at least three cells no smaller
// than the cutoff it walks the half stencil (a cell and its 13 neighbours
// "after" it); otherwise — periodic lengths below three cutoffs, down to one
// particle — a full stencil over as many cells and images as the cutoff
// spans, keeping each pair once by its lower index (and a particle's pairs
// with its own images by the sign of the shift).
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "wearscale/dem/box.hpp"
#include "wearscale/dem/periodic_images.hpp"

namespace wearscale::dem {

class CellGrid {
 public:
  /// Sorts `x` (wrapped into the box on periodic axes) into cells no smaller
  /// than `cut`; at most 4n + 64 cells (open axes spanning far get larger
  /// ones). InputError when the images within `cut` are too many
  /// (PeriodicImages::within).
  /// The particles' cells are found on `threads` threads.
  void build(std::span<const Vec3> x, const Box& box, double cut, int threads = 1);

  const PeriodicImages& images() const { return images_; }

  /// visit(i, j, image, d) once for every physical pair the stencil reaches:
  /// i ≠ j in either order (the caller orders them), or i == j for a
  /// particle and one of its own images (image above zero();
  /// its opposite is the same pair). d = x_j + shift(image) − x_i; the
  /// caller applies its own distance test.
  /// Only the home cells of layers [z_begin, z_end) along z (-1: to the
  /// last): threads may split the search by layers.
  template <class Visit>
  void for_each_candidate(std::span<const Vec3> x, Visit&& visit, int z_begin = 0, int z_end = -1) const;
  /// Cell layers along z.
  int layers() const { return cells_[2]; }
  /// The layers [begin, end) of part `part` of `parts` runs of consecutive
  /// layers holding about equal numbers of particles (a system denser at
  /// one end, e.g. a substrate under empty space, splits where its particles
  /// are, not where its layers are).
  std::pair<int, int> layer_range(int part, int parts) const;

 private:
  std::size_t flat(int cx, int cy, int cz) const {
    return static_cast<std::size_t>(cx) +
           static_cast<std::size_t>(cells_[0]) *
               (static_cast<std::size_t>(cy) + static_cast<std::size_t>(cells_[1]) * static_cast<std::size_t>(cz));
  }
  // The cell a stencil offset reaches along axis a from cell c, and the
  // image shift it crosses; false when it leaves an open axis or goes beyond
  // the images' reach.
  bool step(std::size_t a, int c, int offset, int& cell, int& shift) const;

  std::array<int, 3> cells_{1, 1, 1};
  std::array<int, 3> span_{1, 1, 1};  // stencil half-width in cells
  std::array<bool, 3> periodic_{};
  bool half_stencil_ = true;
  PeriodicImages images_;
  std::array<Vec3, PeriodicImages::max_count> shift_{};
  // The particles sorted by cell: cell c's are order_[start_[c] .. start_[c + 1]).
  std::vector<std::uint32_t> start_, order_;
  std::vector<std::uint32_t> cell_;  // each particle's cell, while sorting
};

template <class Visit>
void CellGrid::for_each_candidate(std::span<const Vec3> x, Visit&& visit, int z_begin, int z_end) const {
  const std::uint8_t zero = images_.zero();
  if (z_end < 0) z_end = cells_[2];
  if (half_stencil_) {
    static constexpr int stencil[13][3] = {{1, 0, 0},  {-1, 1, 0}, {0, 1, 0},  {1, 1, 0},  {-1, -1, 1},
                                           {0, -1, 1}, {1, -1, 1}, {-1, 0, 1}, {0, 0, 1},  {1, 0, 1},
                                           {-1, 1, 1}, {0, 1, 1},  {1, 1, 1}};
    for (int cz = z_begin; cz < z_end; ++cz)
      for (int cy = 0; cy < cells_[1]; ++cy)
        for (int cx = 0; cx < cells_[0]; ++cx) {
          const std::size_t home = flat(cx, cy, cz);
          const std::uint32_t home_begin = start_[home], home_end = start_[home + 1];
          if (home_begin == home_end) continue;
          // The home cell's stencil cells and the images they are met
          // through, once for all its particles.
          std::uint32_t begin[13], end[13];
          std::uint8_t image[13];
          int m = 0;
          for (const auto& o : stencil) {
            std::array<int, 3> c{}, s{};
            if (!step(0, cx, o[0], c[0], s[0]) || !step(1, cy, o[1], c[1], s[1]) || !step(2, cz, o[2], c[2], s[2]))
              continue;
            const std::size_t cell = flat(c[0], c[1], c[2]);
            begin[m] = start_[cell];
            end[m] = start_[cell + 1];
            if (begin[m] == end[m]) continue;
            image[m++] = images_.index(s[0], s[1], s[2]);
          }
          for (std::uint32_t a = home_begin; a < home_end; ++a) {
            const std::uint32_t i = order_[a];
            const Vec3 xi = x[i];
            for (std::uint32_t b = a + 1; b < home_end; ++b) visit(i, order_[b], zero, x[order_[b]] - xi);
            for (int o = 0; o < m; ++o) {
              const Vec3 xs = shift_[image[o]] - xi;
              for (std::uint32_t b = begin[o]; b < end[o]; ++b) visit(i, order_[b], image[o], x[order_[b]] + xs);
            }
          }
        }
    return;
  }
  for (int cz = z_begin; cz < z_end; ++cz)
    for (int cy = 0; cy < cells_[1]; ++cy)
      for (int cx = 0; cx < cells_[0]; ++cx) {
        const std::size_t home = flat(cx, cy, cz);
        for (std::uint32_t a = start_[home]; a < start_[home + 1]; ++a) {
          const std::uint32_t i = order_[a];
          const Vec3 xi = x[i];
          std::array<int, 3> c{}, s{};
          for (int oz = -span_[2]; oz <= span_[2]; ++oz) {
            if (!step(2, cz, oz, c[2], s[2])) continue;
            for (int oy = -span_[1]; oy <= span_[1]; ++oy) {
              if (!step(1, cy, oy, c[1], s[1])) continue;
              for (int ox = -span_[0]; ox <= span_[0]; ++ox) {
                if (!step(0, cx, ox, c[0], s[0])) continue;
                const std::uint8_t sh = images_.index(s[0], s[1], s[2]);
                const Vec3 xs = shift_[sh] - xi;
                const std::size_t cell = flat(c[0], c[1], c[2]);
                for (std::uint32_t b = start_[cell]; b < start_[cell + 1]; ++b) {
                  const std::uint32_t j = order_[b];
                  if (j < i || (j == i && sh <= zero)) continue;  // the same pair from its other end
                  visit(i, j, sh, x[j] + xs);
                }
              }
            }
          }
        }
      }
}

inline bool CellGrid::step(std::size_t a, int c, int offset, int& cell, int& shift) const {
  cell = c + offset;
  shift = 0;
  if (cell >= 0 && cell < cells_[a]) return true;
  if (!periodic_[a]) return false;
  // Floor division: the periods crossed.
  shift = cell >= 0 ? cell / cells_[a] : -((-cell + cells_[a] - 1) / cells_[a]);
  cell -= shift * cells_[a];
  return shift >= -images_.reach[a] && shift <= images_.reach[a];
}

}  // namespace wearscale::dem
