// The MPI layer of a process started without a launcher: serial, rank 0 of 1,
// and every collective the identity (the ranks' tests run under mpirun:
// tests/mpi/mpi_probe.cpp).
#include <gtest/gtest.h>

#include <vector>

#include "wearscale/core/mpi.hpp"

using namespace wearscale;

TEST(Mpi, AProcessStartedAloneIsRankZeroOfOneAndItsSumsAreItsValues) {
  int argc = 1;
  char name[] = "test_core";
  char* args[] = {name, nullptr};
  char** argv = args;
  mpi::Session session(argc, argv);
  EXPECT_FALSE(mpi::active());
  EXPECT_EQ(mpi::rank(), 0);
  EXPECT_EQ(mpi::size(), 1);
  EXPECT_TRUE(mpi::is_root());
  EXPECT_EQ(mpi::sum(0.1), 0.1);
  EXPECT_EQ(mpi::sum(7LL), 7LL);
  EXPECT_EQ(mpi::max(-3.0), -3.0);
  std::vector<double> v = {1.0, 2.5};
  mpi::sum(v);
  EXPECT_EQ(v, (std::vector<double>{1.0, 2.5}));
  mpi::barrier();
}
