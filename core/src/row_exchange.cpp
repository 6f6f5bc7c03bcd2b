#include "wearscale/core/row_exchange.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/mpi.hpp"

#ifdef WEARSCALE_MPI
#include <mpi.h>
#endif

namespace wearscale {

struct RowExchange::Plan {
  // Per rank, in rows: what this rank sends from `from` and receives into `to` (forward).
  std::vector<int> send_counts, send_offsets, recv_counts, recv_offsets;
#ifdef WEARSCALE_MPI
  MPI_Datatype row = MPI_DATATYPE_NULL;
#endif
  bool distributed = false;
};

namespace {
// Rows common to a and b, as an offset into a and a count.
std::array<std::size_t, 2> overlap(RowRange a, RowRange b) {
  const std::size_t lo = std::max(a.first, b.first), hi = std::min(a.first + a.rows, b.first + b.rows);
  return hi > lo ? std::array{lo - a.first, hi - lo} : std::array<std::size_t, 2>{0, 0};
}
}  // namespace

RowExchange::RowExchange(RowRange from, RowRange to, std::size_t row_length)
    : from_(from), to_(to), row_length_(row_length), plan_(std::make_unique<Plan>()) {
  const int ranks = mpi::size();
  if (!mpi::active() || ranks == 1) {
    if (from.first != to.first || from.rows != to.rows)
      throw std::invalid_argument("RowExchange: one process holds different rows in the two distributions");
    return;
  }
#ifdef WEARSCALE_MPI
  const auto p = static_cast<std::size_t>(ranks);
  unsigned long long mine[4] = {from.first, from.rows, to.first, to.rows};
  std::vector<unsigned long long> all(4 * p);
  MPI_Allgather(mine, 4, MPI_UNSIGNED_LONG_LONG, all.data(), 4, MPI_UNSIGNED_LONG_LONG, MPI_COMM_WORLD);
  Plan& plan = *plan_;
  plan.distributed = true;
  for (auto* v : {&plan.send_counts, &plan.send_offsets, &plan.recv_counts, &plan.recv_offsets}) v->assign(p, 0);
  std::size_t from_total = 0, to_total = 0, sent = 0, received = 0;
  for (std::size_t r = 0; r < p; ++r) {
    const RowRange their_from{all[4 * r], all[4 * r + 1]}, their_to{all[4 * r + 2], all[4 * r + 3]};
    from_total += their_from.rows;
    to_total += their_to.rows;
    const auto [send_at, send_rows] = overlap(from, their_to);
    const auto [recv_at, recv_rows] = overlap(to, their_from);
    plan.send_counts[r] = static_cast<int>(send_rows);
    plan.send_offsets[r] = static_cast<int>(send_at);
    plan.recv_counts[r] = static_cast<int>(recv_rows);
    plan.recv_offsets[r] = static_cast<int>(recv_at);
    sent += send_rows;
    received += recv_rows;
  }
  if (from_total != to_total || sent != from.rows || received != to.rows)
    throw std::invalid_argument(fmt::format("RowExchange: the distributions do not cover the same rows once ({} rows "
                                            "against {}; rank {} sends {} of its {} and receives {} of its {})",
                                            from_total, to_total, mpi::rank(), sent, from.rows, received, to.rows));
  MPI_Type_contiguous(static_cast<int>(row_length), MPI_DOUBLE, &plan.row);
  MPI_Type_commit(&plan.row);
#endif
}

RowExchange::~RowExchange() {
#ifdef WEARSCALE_MPI
  if (plan_ && plan_->row != MPI_DATATYPE_NULL) MPI_Type_free(&plan_->row);
#endif
}

void RowExchange::forward(const double* from, double* to) const { move(from, to, from_.rows, false); }

void RowExchange::backward(const double* to, double* from) const { move(to, from, to_.rows, true); }

void RowExchange::move(const double* source, double* destination, std::size_t rows, bool reverse) const {
  if (!plan_->distributed) {
    if (rows > 0) std::memcpy(destination, source, rows * row_length_ * sizeof(double));
    return;
  }
#ifdef WEARSCALE_MPI
  const Plan& p = *plan_;
  // Backward, the counts and offsets of the two sides trade places.
  const std::vector<int>& send_counts = reverse ? p.recv_counts : p.send_counts;
  const std::vector<int>& send_offsets = reverse ? p.recv_offsets : p.send_offsets;
  const std::vector<int>& recv_counts = reverse ? p.send_counts : p.recv_counts;
  const std::vector<int>& recv_offsets = reverse ? p.send_offsets : p.recv_offsets;
  MPI_Alltoallv(source, send_counts.data(), send_offsets.data(), p.row, destination, recv_counts.data(),
                recv_offsets.data(), p.row, MPI_COMM_WORLD);
#endif
}

}  // namespace wearscale
