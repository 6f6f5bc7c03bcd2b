// The XDMF sidecar shows the HDF5 fields in ParaView's XY plane with x along
// X: views with x fastest, 1 × ny × nx points, double-precision geometry,
// and snapshots as a temporal collection.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "wearscale/core/field.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/xdmf.hpp"
#include "xdmf_check.hpp"

using namespace wearscale;
using ::testing::HasSubstr;

namespace {

std::string slurp(const std::filesystem::path& p) {
  std::stringstream ss;
  ss << std::ifstream(p).rdbuf();
  return ss.str();
}

// f(x_i, y_j) = 100 i + j: every point tells where it sits.
RealField labelled(const Grid2D& g) {
  RealField f(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) f(i, j) = 100.0 * static_cast<double>(i) + static_cast<double>(j);
  return f;
}

struct TempDir {
  std::filesystem::path path;
  explicit TempDir(const char* name) : path(std::filesystem::temp_directory_path() / name) {
    std::filesystem::remove_all(path);
    std::filesystem::create_directories(path);
  }
  ~TempDir() { std::filesystem::remove_all(path); }
};

}  // namespace

TEST(Xdmf, AViewHoldsTheFieldWithXFastest) {
  const TempDir dir("wearscale_xdmf_view");
  const Grid2D g(5, 3, 5e-3, 3e-3);  // nx ≠ ny catches a swapped axis
  {
    H5Writer h5(dir.path / "f.h5");
    h5.write_field("/fields/p", labelled(g), "Pa");
    h5.write_transposed_view("/xdmf/fields/p", "/fields/p");
    h5.commit();
  }
  const H5Reader r(dir.path / "f.h5");
  EXPECT_EQ(r.shape("/xdmf/fields/p"), (std::vector<std::size_t>{3, 5}));
  const auto v = r.read_series("/xdmf/fields/p");
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) EXPECT_EQ(v[j * g.nx + i], 100.0 * double(i) + double(j)) << i << "," << j;
}

TEST(Xdmf, DescribesTheXYPlaneInDoublePrecision) {
  const TempDir dir("wearscale_xdmf_test");
  const Grid2D g(128, 64, 2e-3, 1e-3);
  XdmfSidecar sidecar(g);
  {
    H5Writer h5(dir.path / "run.h5");
    h5.write_field("/fields/pressure", labelled(g));
    h5.write_field("/fields/gap", labelled(g));
    sidecar.add(h5, {{"/fields/pressure", "pressure"}, {"/fields/gap", "gap"}});
    h5.commit();
  }
  sidecar.write(dir.path / "run.xdmf", dir.path / "run.h5");
  const auto xml = slurp(dir.path / "run.xdmf");
  EXPECT_THAT(xml, HasSubstr("TopologyType=\"3DCoRectMesh\" Dimensions=\"1 64 128\""));
  EXPECT_THAT(xml, HasSubstr("run.h5:/xdmf/fields/pressure"));  // relative to the sidecar
  EXPECT_THAT(xml, HasSubstr("Name=\"gap\""));
  // Spacing 2e-3/128 = 1.5625e-5 along x and y, written in z, y, x order.
  expect_xdmf_describes(dir.path / "run.xdmf", dir.path / "run.h5", {128, 64}, {"/fields/pressure", "/fields/gap"},
                        std::array<double, 4>{0.0, 0.0, 1.5625e-5, 1.5625e-5});
}

TEST(Xdmf, TheFirstNodeSitsAtTheOriginGiven) {
  // A map's cell-centred samples start half a cell in, here at (0.625, −0.875);
  // its spacing 0.1/3 is one that float32 would round.
  const TempDir dir("wearscale_xdmf_origin");
  const Grid2D g(3, 8, 0.1, 2.0);
  XdmfSidecar sidecar(g, {0.625, -0.875});
  {
    H5Writer h5(dir.path / "map.h5");
    h5.write_field("/region", labelled(g));
    sidecar.add(h5, {{"/region", "region"}});
    h5.commit();
  }
  sidecar.write(dir.path / "map.xdmf", dir.path / "map.h5");
  expect_xdmf_describes(dir.path / "map.xdmf", dir.path / "map.h5", {3, 8}, {"/region"},
                        std::array<double, 4>{0.625, -0.875, 0.1 / 3.0, 0.25});
}

TEST(Xdmf, SnapshotsFormATemporalCollectionInTheOrderAdded) {
  const TempDir dir("wearscale_xdmf_series");
  const Grid2D g(4, 6, 1.0, 1.0);
  XdmfSidecar series(g);
  const std::vector<double> distances = {0.0, 1.6e-4, 3.2e-4};
  {
    H5Writer h5(dir.path / "run.h5");
    for (std::size_t k = 0; k < distances.size(); ++k) {
      const std::string group = "/macro/fields/" + std::to_string(k);
      h5.write_field(group + "/pin", labelled(g));
      series.add_step(h5, distances[k], {{group + "/pin", "pin"}});
    }
    EXPECT_THROW(series.add(h5, {{"/macro/fields/0/pin", "pin"}}), std::logic_error) << "a series is not one grid";
    h5.commit();
  }
  series.write(dir.path / "fields.xdmf", dir.path / "run.h5", "s", "m");
  const auto steps = expect_xdmf_time_series(dir.path / "fields.xdmf", dir.path / "run.h5", {4, 6});
  ASSERT_EQ(steps.size(), 3u);
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_EQ(steps[k].first, distances[k]);
    EXPECT_THAT(steps[k].second, ::testing::ElementsAre("/macro/fields/" + std::to_string(k) + "/pin"));
  }
  EXPECT_THAT(slurp(dir.path / "fields.xdmf"), HasSubstr("Name=\"s = 0.00016 m\""));
}
