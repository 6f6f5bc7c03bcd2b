// Run under mpirun by ctest (tests/CMakeLists.txt, label "mpi"):
//   mpi_probe ranks P   every rank sees P ranks, distinct ranks, and sums that
//                       equal the serial sum in rank order on every rank;
//   mpi_probe abort     rank 1 fails while the others wait at a barrier: the
//                       job must end (non-zero) instead of hanging.
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "wearscale/core/mpi.hpp"

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
