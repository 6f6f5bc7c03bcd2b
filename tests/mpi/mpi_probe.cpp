// Run under mpirun by ctest (tests/CMakeLists.txt, label "mpi"):
//   mpi_probe ranks P   every rank sees P ranks, distinct ranks, and sums that
//                       equal the serial sum in rank order on every rank;
//                       element-wise maxima and minima, rank 0's values
//                       scattered in rank order, and the rows next to each
//                       rank's slab of a periodic grid (some ranks holding
//                       none) arrive where they belong;
//   mpi_probe abort     rank 1 fails while the others wait at a barrier: the
//                       job must end (non-zero) instead of hanging.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "wearscale/core/mpi.hpp"
#include "wearscale/core/row_halo.hpp"

namespace mpi = wearscale::mpi;

namespace {
int check(bool ok, const char* what) {
  if (!ok) std::fprintf(stderr, "rank %d: %s\n", mpi::rank(), what);
  return ok ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv) {
  mpi::Session session(argc, argv);
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "ranks" && argc > 2) {
    const int p = std::atoi(argv[2]);
    int failures = check(mpi::built_with_mpi() && mpi::active(), "MPI is not active under mpirun");
    failures += check(mpi::size() == p, "wrong number of ranks");
    const long long r = mpi::rank();
    failures += check(mpi::sum(r) == static_cast<long long>(p) * (p - 1) / 2, "ranks are not 0..P-1");
    // Values whose floating-point sum depends on the order: rank order on every rank.
    std::vector<double> v = {1e16 * (r % 2 == 0 ? 1.0 : -1.0), 0.1 * static_cast<double>(r + 1)};
    mpi::sum(v);
    double serial0 = 0.0, serial1 = 0.0;
    for (int k = 0; k < p; ++k) {
      serial0 += 1e16 * (k % 2 == 0 ? 1.0 : -1.0);
      serial1 += 0.1 * static_cast<double>(k + 1);
    }
    failures += check(v[0] == serial0 && v[1] == serial1, "sum differs from the serial sum in rank order");
    failures += check(mpi::max(static_cast<double>(r)) == p - 1.0, "max of the ranks");
    std::vector<double> up = {static_cast<double>(r), -static_cast<double>(r)}, down = up;
    mpi::max(up);
    mpi::min(down);
    failures += check(up[0] == p - 1.0 && up[1] == 0.0 && down[0] == 0.0 && down[1] == 1.0 - p,
                      "element-wise max and min of the ranks");
    // Rank k receives k + 1 values k(k+1)/2, ... from rank 0's 0, 1, 2, ...
    std::vector<double> all(mpi::is_root() ? static_cast<std::size_t>(p * (p + 1) / 2) : 0);
    for (std::size_t k = 0; k < all.size(); ++k) all[k] = static_cast<double>(k);
    std::vector<double> part(static_cast<std::size_t>(r + 1));
    mpi::scatter(all, part);
    bool scattered = true;
    for (std::size_t k = 0; k < part.size(); ++k) scattered = scattered && part[k] == static_cast<double>(r * (r + 1) / 2) + k;
    failures += check(scattered, "rank 0's values scattered in rank order");
    // A periodic grid of rows, rank k holding k + 1 rows but the odd ranks none
    // (all of them when serial); each row's values are its index, 3 a row.
    std::size_t first = 0, total = 0;
    for (int k = 0; k < p; ++k) {
      const std::size_t n = (k % 2 == 1) ? 0 : static_cast<std::size_t>(k + 1);
      if (k < r) first += n;
      total += n;
    }
    const std::size_t rows = (r % 2 == 1) ? 0 : static_cast<std::size_t>(r + 1);
    const auto row = [](std::size_t i) { return std::vector<double>(3, static_cast<double>(i)); };
    std::vector<double> before(3, -1.0), after(3, -1.0);
    wearscale::exchange_row_halo({first, rows}, row(first), row(first + rows - 1), before, after);
    if (rows > 0)
      failures += check(before == row((first + total - 1) % total) && after == row((first + rows) % total),
                        "the rows next to the slab");
    mpi::barrier();
    if (mpi::is_root()) std::printf("%d ranks: %s\n", p, failures == 0 ? "ok" : "FAILED");
    return failures == 0 ? 0 : 1;
  }
  if (mode == "abort") {
    if (mpi::rank() == 1) mpi::abort(2);
    mpi::barrier();  // never passed by rank 1: without the abort the others wait here forever
    return 0;
  }
  std::fprintf(stderr, "usage: mpi_probe ranks P | abort\n");
  return 2;
}
