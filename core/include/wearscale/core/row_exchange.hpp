#pragma once
// Rows of a grid moved between two distributions over the ranks of the job.
// In one, rank r holds the rows `from` of the grid; in the other, the rows
// `to`; both distributions cover the same rows [0, R) once. A zero-padded
// half-space held in the slabs of its padded grid takes the contact's rows
// from the contact's own slabs this way (bem::SlabFreeHalfSpace). One row is
// the unit of MPI_Alltoallv, so the counts stay small at any grid size. The
// plan is made once, collectively; a move allocates nothing. One process (or
// a serial build): a copy.
#include <cstddef>
#include <memory>
#include <vector>

namespace wearscale {

/// Rows [first, first + rows) of a grid.
struct RowRange {
  std::size_t first = 0, rows = 0;
};

class RowExchange {
 public:
  /// Collective: every rank gives its own two ranges and the same row length.
  /// std::invalid_argument if the ranks' ranges do not cover the same rows once.
  RowExchange(RowRange from, RowRange to, std::size_t row_length);
  ~RowExchange();
  RowExchange(const RowExchange&) = delete;
  RowExchange& operator=(const RowExchange&) = delete;

  /// Collective: `to` (to.rows × row_length values) receives the rows that the
  /// ranks hold in `from` (from.rows × row_length values, this rank's rows).
  void forward(const double* from, double* to) const;
  /// Collective, the reverse: `from` receives the rows that the ranks hold in `to`.
  void backward(const double* to, double* from) const;

 private:
  // `rows` of this rank's source moved to the destination, forward or back.
  void move(const double* source, double* destination, std::size_t rows, bool reverse) const;
  struct Plan;
  RowRange from_, to_;
  std::size_t row_length_;
  std::unique_ptr<Plan> plan_;  // per-rank counts and offsets in rows, the MPI row type
};

}  // namespace wearscale
