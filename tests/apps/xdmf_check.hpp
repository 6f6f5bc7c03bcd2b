#pragma once
// Checks an XDMF sidecar against its HDF5 file: the sidecar is well-formed
// XML (parsed by Boost.PropertyTree, which throws on malformed XML), its
// topology has the map's dimensions, and every attribute names a dataset
// that exists in the HDF5 file with those dimensions.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include <boost/property_tree/ptree.hpp>
#include <boost/property_tree/xml_parser.hpp>
#include <fmt/format.h>

#include "wearscale/core/hdf5_file.hpp"

inline void expect_xdmf_describes(const std::filesystem::path& xmf, const std::filesystem::path& h5,
                                  const std::vector<std::size_t>& shape, const std::vector<std::string>& datasets) {
  namespace pt = boost::property_tree;
  ASSERT_TRUE(std::filesystem::exists(xmf)) << xmf;
  pt::ptree tree;
  try {
    pt::read_xml(xmf.string(), tree);
  } catch (const pt::xml_parser_error& e) {
    FAIL() << xmf << " is not well-formed XML: " << e.what();
  }
  const std::string dims = fmt::format("{} {}", shape.at(0), shape.at(1));
  const auto& grid = tree.get_child("Xdmf.Domain.Grid");
  EXPECT_EQ(grid.get<std::string>("Topology.<xmlattr>.TopologyType"), "2DCoRectMesh");
  EXPECT_EQ(grid.get<std::string>("Topology.<xmlattr>.Dimensions"), dims);
  const wearscale::H5Reader reader(h5);
  std::vector<std::string> named;
  for (const auto& [tag, attribute] : grid) {
    if (tag != "Attribute") continue;
    const auto& item = attribute.get_child("DataItem");
    EXPECT_EQ(item.get<std::string>("<xmlattr>.Format"), "HDF");
    EXPECT_EQ(item.get<std::string>("<xmlattr>.Dimensions"), dims);
    const auto ref = item.get_value<std::string>();  // "<file relative to the sidecar>:<dataset>"
    const auto colon = ref.find(':');
    ASSERT_NE(colon, std::string::npos) << ref;
    EXPECT_EQ(xmf.parent_path() / ref.substr(0, colon), h5);
    const std::string dataset = ref.substr(colon + 1);
    ASSERT_TRUE(reader.exists(dataset)) << dataset;
    EXPECT_EQ(reader.shape(dataset), shape) << dataset;
    named.push_back(dataset);
  }
  EXPECT_THAT(named, ::testing::UnorderedElementsAreArray(datasets));
}
