// Topographies in and out: text grids (as CSV tools write them) and HDF5 read
// back what was written; malformed files are refused with file, line and column.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/topography_io.hpp"
#include "xdmf_check.hpp"
#include "scratch_dir.hpp"

using namespace wearscale;
using namespace wearscale::bem;
namespace fs = std::filesystem;
using ::testing::HasSubstr;

namespace {
fs::path scratch(const std::string& name) {
  static const ScratchDir dir("wearscale_topo_");
  return dir.file(name);
}

fs::path write_text(const std::string& name, const std::string& text) {
  const auto p = scratch(name);
  std::ofstream(p) << text;
  return p;
}

RealField sample(const Grid2D& g) {
  RealField h(g);
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j)
      h(i, j) = 1e-6 * std::sin(0.7 * static_cast<double>(i) + 1.3 * static_cast<double>(j)) + 1e-9 * static_cast<double>(i);
  return h;
}

std::string rejection(const fs::path& file, const TopographySize& size = {1.0, 1.0}) {
  try {
    read_topography(file, default_surface_dataset, size);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}
}  // namespace

TEST(TopographyIo, TextGridWithSizeCommentsAndAHeaderRowReadsBack) {
  // "# ..." size comments, a header row of names, rows i, columns j (10 digits).
  const Grid2D g(6, 4, 2e-3, 1e-3);
  const RealField h = sample(g);
  std::string text = "# lx = 2e-3\n# ly = 1 mm\n# heights in m\ny0,y1,y2,y3\n";
  for (std::size_t i = 0; i < g.nx; ++i)
    for (std::size_t j = 0; j < g.ny; ++j) text += fmt::format("{:.10g}{}", h(i, j), j + 1 < g.ny ? "," : "\n");
  const RealField back = read_topography(write_text("grid.csv", text));
  ASSERT_EQ(back.grid(), g);
  for (std::size_t k = 0; k < h.size(); ++k) ASSERT_NEAR(back[k], h[k], 1e-15);  // 10 significant digits of ~1e-6
}

TEST(TopographyIo, TextGridRoundTripsExactlyWithAnySeparator) {
  const Grid2D g(5, 7, 1e-4, 1.4e-4);
  const RealField h = sample(g);
  for (const std::string sep : {",", ";", " ", "\t", " ,  ", "  "}) {
    std::string text = "# a comment\n# LX = 100 um\n\n";
    for (std::size_t i = 0; i < g.nx; ++i) {
      for (std::size_t j = 0; j < g.ny; ++j) text += fmt::format("{}{:.17g}", j ? sep : "", h(i, j));
      text += (i % 2 == 0) ? "\r\n" : "\n";
    }
    const RealField back = read_topography_text(write_text("exact.txt", text));
    ASSERT_EQ(back.grid().nx, g.nx);
    ASSERT_EQ(back.grid().ny, g.ny);
    EXPECT_DOUBLE_EQ(back.grid().lx, 1e-4);
    EXPECT_DOUBLE_EQ(back.grid().ly, 1.4e-4);  // square pixels: ly = lx·ny/nx
    for (std::size_t k = 0; k < h.size(); ++k) ASSERT_EQ(back[k], h[k]) << "separator '" << sep << "'";
  }
}

TEST(TopographyIo, SizesGivenByTheCallerOverrideTheFile) {
  const auto path = write_text("sized.txt", "# lx = 1\n# ly = 2\n1 2\n3 4\n");
  EXPECT_EQ(read_topography_text(path).grid(), Grid2D(2, 2, 1.0, 2.0));
  EXPECT_EQ(read_topography_text(path, {5.0, 6.0}).grid(), Grid2D(2, 2, 5.0, 6.0));
}

TEST(TopographyIo, RaggedRowsAreRefusedWithTheLineNumber) {
  const auto path = write_text("ragged.csv", "# lx = 1\n1,2,3\n4,5,6\n7,8\n");
  const std::string msg = rejection(path);
  EXPECT_THAT(msg, HasSubstr(path.string()));
  EXPECT_THAT(msg, HasSubstr("line 4"));
  EXPECT_THAT(msg, HasSubstr("2 values"));
  EXPECT_THAT(msg, HasSubstr("(line 2) has 3"));
}

TEST(TopographyIo, NonNumbersAreRefusedWithLineAndColumn) {
  const auto path = write_text("word.txt", "1 2 3\n4 5 6\n7 x8 9\n");
  const std::string msg = rejection(path);
  EXPECT_THAT(msg, HasSubstr(path.string()));
  EXPECT_THAT(msg, HasSubstr("line 3, column 2"));
  EXPECT_THAT(msg, HasSubstr("'x8' is not a number"));
  EXPECT_THAT(rejection(write_text("empty_value.csv", "1,2\n3,,4\n")), HasSubstr("line 2, column 2: an empty value"));
  EXPECT_THAT(rejection(write_text("trailing.csv", "1,2,\n")), HasSubstr("line 1, column 3"));
}

TEST(TopographyIo, NanIsAMissingPointAndInfinityIsRefused) {
  // nan marks a missing point: refused unless the user chooses to fill it.
  const std::string nan = rejection(write_text("nan.txt", "1 2\n3 nan\n"));
  EXPECT_THAT(nan, HasSubstr("1 of 4 points"));
  EXPECT_THAT(nan, HasSubstr("(the first at line 2, column 2)"));
  EXPECT_THAT(nan, HasSubstr("missing = fill"));
  TopographyOptions fill;
  fill.size = {1.0, 1.0};
  fill.missing = MissingPoints::Fill;
  const auto filled = read_measured_topography(write_text("nan.txt", "1 2\n3 nan\n"), fill);
  EXPECT_EQ(filled.missing, 1u);
  EXPECT_DOUBLE_EQ(filled.heights(1, 1), 2.5) << "the mean of its two measured neighbours (3 and 2)";
  EXPECT_THAT(rejection(write_text("inf.txt", "1 -inf\n3 4\n")), HasSubstr("line 1, column 2"));
  EXPECT_THAT(rejection(write_text("huge.txt", "1 1e400\n3 4\n")), HasSubstr("line 1, column 2"));
  EXPECT_THAT(rejection(write_text("allnan.txt", "nan nan\nnan nan\n")), HasSubstr("every one of its 4 points"));
}

TEST(TopographyIo, EmptyFilesMissingFilesAndMissingSizesAreRefused) {
  EXPECT_THAT(rejection(write_text("empty.txt", "")), HasSubstr("no height data"));
  EXPECT_THAT(rejection(write_text("comments.txt", "# lx = 1\n\n# only comments\n")), HasSubstr("no height data"));
  EXPECT_THAT(rejection(scratch("absent.txt")), HasSubstr("no such topography file"));
  const auto unsized = write_text("unsized.txt", "1 2\n3 4\n");
  EXPECT_THAT(rejection(unsized, {}), HasSubstr("size of the topography is not given"));
  EXPECT_THAT(rejection(write_text("badsize.txt", "# lx = 3 kg\n1 2\n3 4\n"), {}), HasSubstr("line 1: lx = '3 kg'"));
}

TEST(TopographyIo, Hdf5RoundTripWithXdmfSidecar) {
  const Grid2D g(32, 24, 1e-4, 7.5e-5);
  const RealField h = sample(g);
  const auto path = scratch("surface.h5");
  const auto sidecar = write_surface(path, h);
  EXPECT_EQ(sidecar, scratch("surface.xdmf"));
  ASSERT_TRUE(fs::exists(sidecar));
  std::stringstream xml_text;
  xml_text << std::ifstream(sidecar).rdbuf();
  const std::string xml = xml_text.str();
  EXPECT_THAT(xml, HasSubstr("surface.h5:/xdmf/surface/height"));
  expect_xdmf_describes(sidecar, path, {32, 24}, {"/surface/height"}, std::array<double, 4>{0.0, 0.0, g.dx(), g.dy()});

  const RealField back = read_topography(path);
  ASSERT_EQ(back.grid(), g);
  for (std::size_t k = 0; k < h.size(); ++k) ASSERT_EQ(back[k], h[k]);
  EXPECT_EQ(H5Reader(path).string_attribute("/surface/height", "unit"), "m");
}

TEST(TopographyIo, Hdf5WithoutSizeOrDatasetIsRefused) {
  const auto path = scratch("bare.h5");
  {
    H5Writer w(path);
    w.write_series("/other", std::vector<double>{1.0, 2.0});
    w.commit();
  }
  try {
    read_topography(path, "/surface/height");
    FAIL() << "a missing dataset was read";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no dataset '/surface/height'"));
  }
  EXPECT_THAT(rejection(path), HasSubstr("no dataset"));
}
