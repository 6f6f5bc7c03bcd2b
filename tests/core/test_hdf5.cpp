// HDF5 output: what is written reads back identically, and an output file
// appears under its final name only once complete.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <numeric>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/hdf5_file.hpp"

using namespace wearscale;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("wearscale_h5_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  return dir / name;
}

std::size_t files_in(const fs::path& dir) {
  return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}
}  // namespace

TEST(HDF5, SeriesTableFieldAndAttributesReadBack) {
  const auto path = scratch("roundtrip.h5");
  std::vector<double> t(100), mu(100);
  std::iota(t.begin(), t.end(), 0.0);
  for (std::size_t k = 0; k < mu.size(); ++k) mu[k] = 0.14 + 1e-3 * static_cast<double>(k);
  RealField p(Grid2D(64, 32, 2e-3, 1e-3));
  for (std::size_t k = 0; k < p.size(); ++k) p[k] = std::sin(static_cast<double>(k));
  {
    H5Writer w(path);
    w.write_series("/series/time", t, "s");
    w.write_table("/curves/friction", {"s", "mu"}, {t, mu}, {"m", "1"});
    w.write_field("/fields/pressure", p, "Pa");
    w.write_scalar("/results/mu_mean", 0.5, "1");
    w.set_attribute("/", "provenance", "macro/bem-pin-on-disc");
    w.set_attribute("/fields/pressure", "time", 1.25);
    w.commit();
  }
  H5Reader r(path);
  EXPECT_EQ(r.read_series("/series/time"), t);
  EXPECT_EQ(r.read_series("/curves/friction/mu"), mu);
  EXPECT_EQ(r.string_attribute("/curves/friction", "columns"), "s,mu");
  EXPECT_EQ(r.string_attribute("/series/time", "unit"), "s");
  EXPECT_EQ(r.read_scalar("/results/mu_mean"), 0.5);
  EXPECT_EQ(r.string_attribute("/", "provenance"), "macro/bem-pin-on-disc");
  EXPECT_EQ(r.number_attribute("/fields/pressure", "time"), 1.25);
  const RealField q = r.read_field("/fields/pressure");
  EXPECT_EQ(q.grid(), p.grid());
  for (std::size_t k = 0; k < p.size(); ++k) ASSERT_EQ(q[k], p[k]);
  EXPECT_FALSE(r.exists("/fields/gap"));
  EXPECT_FALSE(r.exists("/nothing/here"));
  fs::remove_all(path.parent_path());
}

TEST(HDF5, AWriterThatIsNotCommittedLeavesNoFile) {
  const auto path = scratch("aborted.h5");
  try {
    H5Writer w(path);
    w.write_series("/x", std::vector<double>(10, 1.0));
    throw std::runtime_error("solver diverged");
  } catch (const std::runtime_error&) {
  }
  EXPECT_FALSE(fs::exists(path));
  EXPECT_EQ(files_in(path.parent_path()), 0u);  // the partial file is removed too
  fs::remove_all(path.parent_path());
}

TEST(HDF5, AKilledWriterLeavesThePreviousCompleteFile) {
  const auto path = scratch("killed.h5");
  {
    H5Writer w(path);
    w.write_series("/version", std::vector<double>{1.0});
    w.commit();
  }
  const pid_t child = ::fork();
  if (child == 0) {
    H5Writer w(path);
    w.write_series("/version", std::vector<double>{2.0});
    w.write_series("/big", std::vector<double>(1 << 16, 3.0));
    ::kill(::getpid(), SIGKILL);  // dies mid-run, before commit
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  H5Reader r(path);  // still the complete first version
  EXPECT_EQ(r.read_series("/version"), std::vector<double>{1.0});
  fs::remove_all(path.parent_path());
}

TEST(HDF5, ReadingSomethingThatIsNotHDF5IsBadInput) {
  const auto path = scratch("text.h5");
  std::ofstream(path) << "not hdf5";
  EXPECT_THROW(H5Reader{path}, InputError);
  EXPECT_THROW(H5Reader{scratch("missing.h5")}, InputError);
  fs::remove_all(path.parent_path());
}

TEST(HDF5, MissingDatasetIsBadInputNamingIt) {
  const auto path = scratch("small.h5");
  {
    H5Writer w(path);
    w.write_series("/a", std::vector<double>{1.0, 2.0});
    w.commit();
  }
  H5Reader r(path);
  try {
    r.read_field("/heights");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/heights"), std::string::npos);
  }
  EXPECT_THROW(r.read_field("/a"), InputError);  // 1D is not a field
  fs::remove_all(path.parent_path());
}
