// One cache root for every kind of cached result: LAMMPS runs and DEM
// junction strengths are sibling folders under it, wherever it is.
#include <cstdlib>

#include <gtest/gtest.h>

#include "wearscale/core/cache_folder.hpp"

using namespace wearscale;
namespace fs = std::filesystem;

// ctest runs every TEST in its own process: the variables set here end with it.
TEST(CacheFolder, WearscaleCacheIsTheRootOfEveryKind) {
  setenv("WEARSCALE_CACHE", "/scratch/c", 1);
  setenv("XDG_CACHE_HOME", "/x", 1);
  EXPECT_EQ(cache_folder("lammps"), fs::path("/scratch/c/lammps"));
  EXPECT_EQ(cache_folder("dem"), fs::path("/scratch/c/dem"));
}

TEST(CacheFolder, WithoutItTheXdgThenTheHomeCacheHoldsAWearscaleFolder) {
  unsetenv("WEARSCALE_CACHE");
  setenv("XDG_CACHE_HOME", "/x", 1);
  EXPECT_EQ(cache_folder("dem"), fs::path("/x/wearscale/dem"));
  unsetenv("XDG_CACHE_HOME");
  setenv("HOME", "/home/u", 1);
  EXPECT_EQ(cache_folder("lammps"), fs::path("/home/u/.cache/wearscale/lammps"));
  setenv("WEARSCALE_CACHE", "~/c", 1);
  EXPECT_EQ(cache_root(), fs::path("/home/u/c"));
}

TEST(CacheFolder, OnlyALeadingTildeIsHome) {
  setenv("HOME", "/home/u", 1);
  EXPECT_EQ(expand_home("~"), fs::path("/home/u/"));
  EXPECT_EQ(expand_home("~/a/b"), fs::path("/home/u/a/b"));
  EXPECT_EQ(expand_home("a/~/b"), fs::path("a/~/b"));
  EXPECT_EQ(expand_home("~other/b"), fs::path("~other/b"));
}
