#include "wearscale/core/row_halo.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

#include "wearscale/core/mpi.hpp"

#ifdef WEARSCALE_MPI
#include <mpi.h>
#endif

namespace wearscale {

namespace {
void check_lengths(std::span<const double> first, std::span<const double> last, std::span<double> before,
                   std::span<double> after) {
  if (last.size() != first.size() || before.size() != first.size() || after.size() != first.size())
    throw std::invalid_argument("exchange_row_halo: the rows differ in length");
}
}  // namespace

void exchange_row_halo(RowRange mine, std::span<const double> first, std::span<const double> last,
                       std::span<double> before, std::span<double> after) {
  const bool holds = mine.rows > 0;
  if (holds) check_lengths(first, last, before, after);
#ifdef WEARSCALE_MPI
  if (mpi::active() && mpi::size() > 1) {
    const int ranks = mpi::size();
    std::vector<unsigned long long> ranges(2 * static_cast<std::size_t>(ranks));
    const unsigned long long own[2] = {mine.first, mine.rows};
    MPI_Allgather(own, 2, MPI_UNSIGNED_LONG_LONG, ranges.data(), 2, MPI_UNSIGNED_LONG_LONG, MPI_COMM_WORLD);
    unsigned long long total = 0;
    for (int r = 0; r < ranks; ++r) {
      const auto f = ranges[2 * static_cast<std::size_t>(r)], n = ranges[2 * static_cast<std::size_t>(r) + 1];
      if (n > 0 && f != total) throw std::invalid_argument("exchange_row_halo: the ranks' rows do not tile the grid");
      total += n;
    }
    if (!holds) return;
    const auto owner = [&](unsigned long long row) {  // the rank whose range holds `row`
      for (int r = 0; r < ranks; ++r) {
        const auto f = ranges[2 * static_cast<std::size_t>(r)], n = ranges[2 * static_cast<std::size_t>(r) + 1];
        if (row >= f && row < f + n) return r;
      }
      return -1;
    };
    const int below = owner((mine.first + total - 1) % total), above = owner((mine.first + mine.rows) % total);
    const int n = static_cast<int>(first.size());
    constexpr int kToAbove = 0, kToBelow = 1;  // which side of the receiver a row lies on
    MPI_Request requests[4];
    MPI_Irecv(before.data(), n, MPI_DOUBLE, below, kToAbove, MPI_COMM_WORLD, &requests[0]);
    MPI_Irecv(after.data(), n, MPI_DOUBLE, above, kToBelow, MPI_COMM_WORLD, &requests[1]);
    MPI_Isend(last.data(), n, MPI_DOUBLE, above, kToAbove, MPI_COMM_WORLD, &requests[2]);
    MPI_Isend(first.data(), n, MPI_DOUBLE, below, kToBelow, MPI_COMM_WORLD, &requests[3]);
    MPI_Waitall(4, requests, MPI_STATUSES_IGNORE);
    return;
  }
#endif
  if (!holds) return;
  std::copy(last.begin(), last.end(), before.begin());
  std::copy(first.begin(), first.end(), after.begin());
}

}  // namespace wearscale
