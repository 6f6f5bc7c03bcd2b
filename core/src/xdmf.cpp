#include "wearscale/core/xdmf.hpp"

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"

namespace wearscale {

void write_xdmf(const std::filesystem::path& xdmf_path, const std::filesystem::path& h5_file, const Grid2D& grid,
                const std::vector<XdmfField>& fields, std::array<double, 2> origin) {
  const auto base = xdmf_path.parent_path().empty() ? std::filesystem::path(".") : xdmf_path.parent_path();
  const auto h5 = std::filesystem::proximate(h5_file, base).string();
  // Fields are stored row-major with y fastest, so the slowest dimension is x:
  // XDMF lists dimensions slowest first, hence (nx, ny) and (dx, dy).
  std::string xml = fmt::format(
      "<?xml version=\"1.0\" ?>\n"
      "<Xdmf Version=\"3.0\">\n"
      " <Domain>\n"
      "  <Grid Name=\"surface\" GridType=\"Uniform\">\n"
      "   <Topology TopologyType=\"2DCoRectMesh\" Dimensions=\"{0} {1}\"/>\n"
      "   <Geometry GeometryType=\"ORIGIN_DXDY\">\n"
      "    <DataItem Format=\"XML\" Dimensions=\"2\">{4:.17g} {5:.17g}</DataItem>\n"
      "    <DataItem Format=\"XML\" Dimensions=\"2\">{2:.17g} {3:.17g}</DataItem>\n"
      "   </Geometry>\n",
      grid.nx, grid.ny, grid.dx(), grid.dy(), origin[0], origin[1]);
  for (const auto& f : fields)
    xml += fmt::format(
        "   <Attribute Name=\"{0}\" AttributeType=\"Scalar\" Center=\"Node\">\n"
        "    <DataItem Format=\"HDF\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"{1} {2}\">{3}:{4}</DataItem>\n"
        "   </Attribute>\n",
        f.name, grid.nx, grid.ny, h5, f.dataset);
  xml += "  </Grid>\n </Domain>\n</Xdmf>\n";
  write_file_atomically(xdmf_path, xml);
}

}  // namespace wearscale
