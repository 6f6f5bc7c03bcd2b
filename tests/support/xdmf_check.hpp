#pragma once
// Checks an XDMF sidecar against its HDF5 file, as ParaView will read it:
// the sidecar is well-formed XML (parsed by Boost.PropertyTree, which throws
// on malformed XML); each grid is one plane of 1 × ny × nx points (the XY
// plane, x fastest) with origin and spacing in double precision; every
// attribute names a view that exists in the HDF5 file with shape ny × nx and
// holds, at [j][i], the stored field's value f(x_i, y_j) at [i][j] — so a
// point ParaView shows at (x_i, y_j) carries wearscale's value there.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <fmt/format.h>

#include "wearscale/io/hdf5_file.hpp"

namespace xdmf_check {

namespace pt = boost::property_tree;

inline std::vector<double> numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> out;
  for (double v; in >> v;) out.push_back(v);
  return out;
}

/// One uniform grid: plane, dimensions, geometry and the views of its attributes.
/// Returns the source datasets its attributes show.
inline std::vector<std::string> check_grid(const pt::ptree& grid, const std::filesystem::path& xmf,
                                           const std::filesystem::path& h5, const std::vector<std::size_t>& shape,
                                           std::optional<std::array<double, 4>> geometry) {
  const std::size_t nx = shape.at(0), ny = shape.at(1);
  const std::string dims = fmt::format("1 {} {}", ny, nx);
  EXPECT_EQ(grid.get<std::string>("Topology.<xmlattr>.TopologyType"), "3DCoRectMesh");
  EXPECT_EQ(grid.get<std::string>("Topology.<xmlattr>.Dimensions"), dims) << "XDMF lists z, y, x: 1 plane, ny, nx";
  EXPECT_EQ(grid.get<std::string>("Geometry.<xmlattr>.GeometryType"), "ORIGIN_DXDYDZ");
  std::vector<std::vector<double>> items;
  for (const auto& [tag, item] : grid.get_child("Geometry")) {
    if (tag != "DataItem") continue;
    EXPECT_EQ(item.get<std::string>("<xmlattr>.Precision", ""), "8") << "geometry read as float64";
    EXPECT_EQ(item.get<std::string>("<xmlattr>.NumberType", ""), "Float");
    items.push_back(numbers(item.get_value<std::string>()));
  }
  EXPECT_EQ(items.size(), 2u) << "origin and spacing";
  if (items.size() == 2 && items[0].size() == 3 && items[1].size() == 3) {
    EXPECT_EQ(items[0][0], 0.0) << "the plane z = 0";
    EXPECT_GT(items[1][1], 0.0);
    EXPECT_GT(items[1][2], 0.0);
    if (geometry) {  // (x0, y0, dx, dy), exact: written with 17 digits
      EXPECT_EQ(items[0][2], (*geometry)[0]) << "origin x";
      EXPECT_EQ(items[0][1], (*geometry)[1]) << "origin y";
      EXPECT_EQ(items[1][2], (*geometry)[2]) << "spacing x";
      EXPECT_EQ(items[1][1], (*geometry)[3]) << "spacing y";
    }
  }
  const wearscale::H5Reader reader(h5);
  std::vector<std::string> sources;
  for (const auto& [tag, attribute] : grid) {
    if (tag != "Attribute") continue;
    const auto& item = attribute.get_child("DataItem");
    EXPECT_EQ(item.get<std::string>("<xmlattr>.Format"), "HDF");
    EXPECT_EQ(item.get<std::string>("<xmlattr>.Precision", ""), "8");
    EXPECT_EQ(item.get<std::string>("<xmlattr>.Dimensions"), dims);
    const auto ref = item.get_value<std::string>();  // "<file relative to the sidecar>:<dataset>"
    const auto colon = ref.rfind(':');
    if (colon == std::string::npos) {
      ADD_FAILURE() << ref;
      continue;
    }
    EXPECT_EQ(std::filesystem::weakly_canonical(xmf.parent_path() / ref.substr(0, colon)),
              std::filesystem::weakly_canonical(h5));
    const std::string view = ref.substr(colon + 1);
    EXPECT_TRUE(view.starts_with("/xdmf/")) << view;
    const std::string source = view.substr(5);
    if (!reader.exists(view) || !reader.exists(source)) {
      ADD_FAILURE() << "missing " << view << " or " << source << " in " << h5;
      continue;
    }
    EXPECT_EQ(reader.shape(view), (std::vector<std::size_t>{ny, nx})) << view;
    EXPECT_EQ(reader.shape(source), (std::vector<std::size_t>{nx, ny})) << source;
    const auto v = reader.read_series(view), f = reader.read_series(source);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < nx && v.size() == f.size(); ++i)
      for (std::size_t j = 0; j < ny; ++j)
        if (!(v[j * nx + i] == f[i * ny + j] || (v[j * nx + i] != v[j * nx + i] && f[i * ny + j] != f[i * ny + j])))
          ++wrong;
    EXPECT_EQ(wrong, 0u) << view << " is not " << source << " with x fastest";
    sources.push_back(source);
  }
  return sources;
}

inline pt::ptree parse(const std::filesystem::path& xmf) {
  pt::ptree tree;
  try {
    pt::read_xml(xmf.string(), tree);
  } catch (const pt::xml_parser_error& e) {
    ADD_FAILURE() << xmf << " is not well-formed XML: " << e.what();
  }
  return tree;
}

}  // namespace xdmf_check

/// A single-grid sidecar of `datasets` (stored nx × ny, `shape` = {nx, ny});
/// `geometry` = (x0, y0, dx, dy) when given.
inline void expect_xdmf_describes(const std::filesystem::path& xmf, const std::filesystem::path& h5,
                                  const std::vector<std::size_t>& shape, const std::vector<std::string>& datasets,
                                  std::optional<std::array<double, 4>> geometry = std::nullopt) {
  ASSERT_TRUE(std::filesystem::exists(xmf)) << xmf;
  const auto tree = xdmf_check::parse(xmf);
  const auto& grid = tree.get_child("Xdmf.Domain.Grid");
  EXPECT_EQ(grid.get<std::string>("<xmlattr>.GridType"), "Uniform");
  EXPECT_THAT(xdmf_check::check_grid(grid, xmf, h5, shape, geometry),
              ::testing::UnorderedElementsAreArray(datasets));
}

/// A temporal collection; returns each step's time and the datasets it shows.
inline std::vector<std::pair<double, std::vector<std::string>>> expect_xdmf_time_series(
    const std::filesystem::path& xmf, const std::filesystem::path& h5, const std::vector<std::size_t>& shape) {
  std::vector<std::pair<double, std::vector<std::string>>> steps;
  if (!std::filesystem::exists(xmf)) {
    ADD_FAILURE() << "no " << xmf;
    return steps;
  }
  const auto tree = xdmf_check::parse(xmf);
  const auto& collection = tree.get_child("Xdmf.Domain.Grid");
  EXPECT_EQ(collection.get<std::string>("<xmlattr>.GridType"), "Collection");
  EXPECT_EQ(collection.get<std::string>("<xmlattr>.CollectionType"), "Temporal");
  for (const auto& [tag, grid] : collection) {
    if (tag != "Grid") continue;
    steps.emplace_back(grid.get<double>("Time.<xmlattr>.Value"),
                       xdmf_check::check_grid(grid, xmf, h5, shape, std::nullopt));
  }
  return steps;
}
