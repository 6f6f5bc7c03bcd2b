// The XDMF sidecar describes the HDF5 fields as a uniform 2D grid.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "wearscale/core/xdmf.hpp"

using namespace wearscale;
using ::testing::HasSubstr;

TEST(Xdmf, DescribesDimensionsSpacingAndDatasets) {
  const auto dir = std::filesystem::temp_directory_path() / "wearscale_xdmf_test";
  std::filesystem::create_directories(dir);
  const Grid2D g(128, 64, 2e-3, 1e-3);
  write_xdmf(dir / "run.xdmf", dir / "run.h5", g, {{"/fields/pressure", "pressure"}, {"/fields/gap", "gap"}});
  std::stringstream ss;
  ss << std::ifstream(dir / "run.xdmf").rdbuf();
  const auto xml = ss.str();
  EXPECT_THAT(xml, HasSubstr("TopologyType=\"2DCoRectMesh\" Dimensions=\"128 64\""));
  EXPECT_THAT(xml, HasSubstr(">1.5625e-05 1.5625e-05<"));
  EXPECT_THAT(xml, HasSubstr("run.h5:/fields/pressure"));  // relative to the sidecar
  EXPECT_THAT(xml, HasSubstr("Name=\"gap\""));
  EXPECT_THAT(xml, HasSubstr(">0 0<")) << "the first node at the origin by default";
  // Cell-centred samples of [0.5, 1.5] × [−1, 1] on 4 × 8 cells: first node at (0.625, −0.875).
  write_xdmf(dir / "map.xdmf", dir / "map.h5", Grid2D(4, 8, 1.0, 2.0), {{"/region", "region"}}, {0.625, -0.875});
  std::stringstream map;
  map << std::ifstream(dir / "map.xdmf").rdbuf();
  EXPECT_THAT(map.str(), HasSubstr(">0.625 -0.875<"));
  EXPECT_THAT(map.str(), HasSubstr(">0.25 0.25<"));
  std::filesystem::remove_all(dir);
}
