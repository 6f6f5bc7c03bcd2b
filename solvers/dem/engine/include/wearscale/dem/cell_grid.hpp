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
  /// The same candidates as runs of the sorted particles, when the grid
  /// walks the half stencil (half_stencil()): visit(i, image, xs, begin, end)
  /// for the particles in slots [begin, end) of the cell order (order(),
  /// sorted_positions()) met from i through `image`, with d = x_j + xs for
  /// each (xs = shift(image) − x_i). The cells of a stencil row along x that
  /// follow one another in memory make one run (the home cell's particles
  /// after i and the next cell along x, the three cells of each of the four
  /// other rows), so a particle's candidates come in about five runs, its
  /// own cell's first; a search can test them as arrays.
  template <class VisitRun>
  void for_each_run(std::span<const Vec3> x, VisitRun&& visit, int z_begin = 0, int z_end = -1) const;
  /// Cells no smaller than the cutoff and at least three along each periodic
  /// axis: each pair is met once, in runs (for_each_run).
  bool half_stencil() const { return half_stencil_; }
  /// The particles in cell order: slot b holds particle order()[b].
  std::span<const std::uint32_t> order() const { return order_; }
  /// The positions given to build() (wrapped) in cell order, one array per
  /// axis, in single precision (kept for half-stencil grids only): a first,
  /// coarse test of a run's candidates (4 bytes a coordinate; the exact test
  /// reads the positions themselves).
  std::span<const float> sorted_positions(int axis) const { return sorted_[static_cast<std::size_t>(axis)]; }
  /// A bound on the error of a component of x_j + xs computed in single
  /// precision from sorted_positions() and xs rounded to float, against the
  /// same sum in double (xs = shift − x_i of any pair).
  double sorted_position_error() const { return sorted_error_; }
  /// Cell layers along z.
  int layers() const { return cells_[2]; }
  /// The layers [begin, end) of part `part` of `parts` runs of consecutive
  /// layers holding about equal numbers of particles (a system denser at
  /// one end, e.g. a substrate under empty space, splits where its particles
  /// are, not where its layers are).
  std::pair<int, int> layer_range(int part, int parts) const;
  /// A buffer of at least one 32-bit word a particle that the grid needs
  /// only inside build() (each particle's cell while sorting): the caller
  /// may use it between builds, resized as it needs (the neighbour list's
  /// row counts and carry-over flags: no array of its own for them).
  std::vector<std::uint32_t>& scratch() { return scratch_; }

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
  // sorted_ and sorted_error_ from the positions, once order_ is known.
  void sort_positions(std::span<const Vec3> x, int threads);

  std::array<int, 3> cells_{1, 1, 1};
  std::array<int, 3> span_{1, 1, 1};  // stencil half-width in cells
  std::array<bool, 3> periodic_{};
  bool half_stencil_ = true;
  PeriodicImages images_;
  std::array<Vec3, PeriodicImages::max_count> shift_{};
  // The particles sorted by cell: cell c's are order_[start_[c] .. start_[c + 1]).
  std::vector<std::uint32_t> start_, order_;
  std::vector<std::uint32_t> scratch_;  // each particle's cell, while sorting (scratch())
  std::array<std::vector<float>, 3> sorted_;  // x, y, z by slot
  double sorted_error_ = 0.0;
};

template <class VisitRun>
void CellGrid::for_each_run(std::span<const Vec3> x, VisitRun&& visit, int z_begin, int z_end) const {
  const std::uint8_t zero = images_.zero();
  if (z_end < 0) z_end = cells_[2];
  // The half stencil by rows along x, (dy, dz) and the cells dx of each:
  // the home cell's row takes the cell after it, the others three cells.
  static constexpr int rows[5][2] = {{0, 0}, {1, 0}, {-1, 1}, {0, 1}, {1, 1}};
  const std::uint32_t* order = order_.data();
  struct Run {
    std::uint32_t begin, end;
    std::uint8_t image;
  };
  for (int cz = z_begin; cz < z_end; ++cz)
    for (int cy = 0; cy < cells_[1]; ++cy)
      for (int cx = 0; cx < cells_[0]; ++cx) {
        const std::size_t home = flat(cx, cy, cz);
        const std::uint32_t home_begin = start_[home], home_end = start_[home + 1];
        if (home_begin == home_end) continue;
        // The stencil's runs, once for all the home cell's particles: cells
        // next to each other along x and met through the same image join.
        // runs[0] begins with the home cell (from the particle after i).
        Run runs[1 + 13];
        int m = 1;
        runs[0] = {home_begin, home_end, zero};
        for (const auto& row : rows) {
          int cyr = 0, czr = 0, syr = 0, szr = 0;
          if (!step(1, cy, row[0], cyr, syr) || !step(2, cz, row[1], czr, szr)) continue;
          const bool home_row = row[0] == 0 && row[1] == 0;
          int last_cell = home_row ? cx : -2, last_shift = 0;
          for (int dx = home_row ? 1 : -1; dx <= 1; ++dx) {
            int c = 0, sxr = 0;
            if (!step(0, cx, dx, c, sxr)) continue;
            const std::size_t cell = flat(c, cyr, czr);
            Run& open = runs[m - 1];
            if (c == last_cell + 1 && sxr == last_shift && open.end == start_[cell]) {
              open.end = start_[cell + 1];  // the next cell in memory, through the same image
            } else {
              runs[m++] = {start_[cell], start_[cell + 1], images_.index(sxr, syr, szr)};
            }
            last_cell = c;
            last_shift = sxr;
          }
        }
        for (std::uint32_t a = home_begin; a < home_end; ++a) {
          const std::uint32_t i = order[a];
          const Vec3 xi = x[i];
          visit(i, zero, -xi, a + 1, runs[0].end);
          for (int o = 1; o < m; ++o) {
            const Run& run = runs[o];
            if (run.begin != run.end) visit(i, run.image, shift_[run.image] - xi, run.begin, run.end);
          }
        }
      }
}

template <class Visit>
void CellGrid::for_each_candidate(std::span<const Vec3> x, Visit&& visit, int z_begin, int z_end) const {
  const std::uint8_t zero = images_.zero();
  if (z_end < 0) z_end = cells_[2];
  if (half_stencil_) {
    for_each_run(
        x, [&](std::uint32_t i, std::uint8_t image, const Vec3& xs, std::uint32_t begin, std::uint32_t end) {
          for (std::uint32_t b = begin; b < end; ++b) visit(i, order_[b], image, x[order_[b]] + xs);
        },
        z_begin, z_end);
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
