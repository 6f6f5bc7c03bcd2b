// The DEM time series in HDF5: rows of step, time and named columns, written
// with core's H5Writer, committed atomically, read back with H5Reader.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <stdexcept>

#include "wearscale/core/hdf5_file.hpp"
#include "wearscale/dem/time_series.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
using namespace wearscale::dem;
namespace fs = std::filesystem;

namespace {
fs::path scratch(const std::string& name) {
  static const ScratchDir dir("wearscale-dem-series-");
  return dir.file(name);
}
}  // namespace

TEST(TimeSeries, RoundTripsThroughH5Reader) {
  TimeSeries series({"wall_force_x", "kinetic_energy", "worn"}, {"N", "J", ""});
  for (long s = 0; s < 5; ++s) series.append(10 * s, 1e-12 * static_cast<double>(s), {0.5 * s, s * s * 1e-20, 3.0 * s});
  EXPECT_EQ(series.rows(), 5u);
  const auto path = scratch("series.h5");
  series.save(path, "/dem/series");
  H5Reader in(path);
  EXPECT_EQ(in.string_attribute("/dem/series", "columns"), "step,time,wall_force_x,kinetic_energy,worn");
  EXPECT_EQ(in.read_series("/dem/series/step"), (std::vector<double>{0, 10, 20, 30, 40}));
  EXPECT_EQ(in.read_series("/dem/series/time"), series.times());
  EXPECT_EQ(in.read_series("/dem/series/wall_force_x"), series.column("wall_force_x"));
  EXPECT_DOUBLE_EQ(in.read_series("/dem/series/kinetic_energy")[3], 9e-20);
  EXPECT_EQ(in.read_series("/dem/series/worn"), (std::vector<double>{0, 3, 6, 9, 12}));
  EXPECT_EQ(in.string_attribute("/dem/series/wall_force_x", "unit"), "N");
  fs::remove_all(path.parent_path());
}

TEST(TimeSeries, WritesIntoAFileWithOtherContent) {
  TimeSeries series({"stress_zz"});
  series.append(1, 0.1, {-2.0});
  const auto path = scratch("run.h5");
  {
    H5Writer out(path);
    out.write_scalar("/dem/d0", 6e-9, "m");
    series.write(out, "/dem/series");
    EXPECT_FALSE(fs::exists(path));  // appears complete or not at all
    out.commit();
  }
  H5Reader in(path);
  EXPECT_EQ(in.read_scalar("/dem/d0"), 6e-9);
  EXPECT_EQ(in.read_series("/dem/series/stress_zz"), std::vector<double>{-2.0});
  fs::remove_all(path.parent_path());
}

TEST(TimeSeries, RefusesRowsOfTheWrongWidthAndBadNames) {
  TimeSeries series({"a", "b"});
  EXPECT_THROW(series.append(0, 0.0, {1.0}), std::invalid_argument);
  EXPECT_THROW(series.column("c"), std::invalid_argument);
  EXPECT_THROW(TimeSeries({"time"}), std::invalid_argument);
  EXPECT_THROW(TimeSeries({"a", "a"}), std::invalid_argument);
  EXPECT_THROW(TimeSeries({"a/b"}), std::invalid_argument);
  EXPECT_THROW(TimeSeries({"a"}, {"m", "s"}), std::invalid_argument);
}
