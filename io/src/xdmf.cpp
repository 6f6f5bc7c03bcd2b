#include "wearscale/io/xdmf.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale {

namespace {

// '&', '<', '>' and quotes as XML entities, for names inside attributes.
std::string escaped(const std::string& text) {
  std::string out;
  for (const char c : text) switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      default: out += c;
    }
  return out;
}

}  // namespace

std::string xdmf_view(const std::string& dataset) {
  return dataset.starts_with('/') ? "/xdmf" + dataset : "/xdmf/" + dataset;
}

XdmfSidecar::XdmfSidecar(const Grid2D& grid, std::array<double, 2> origin) : grid_(grid), origin_(origin) {}

void XdmfSidecar::add_views(H5Writer& h5, const std::vector<XdmfField>& fields) const {
  for (const auto& f : fields) h5.write_transposed_view(xdmf_view(f.dataset), f.dataset);
  h5.set_attribute("/xdmf", "description",
                   "views of the 2D fields with x fastest (ny × nx), read by the .xdmf sidecar (ParaView); "
                   "HDF5 virtual datasets onto the stored fields, no copy");
}

XdmfSidecar& XdmfSidecar::add(H5Writer& h5, const std::vector<XdmfField>& fields) {
  if (!steps_.empty() && steps_.front().time)
    throw std::logic_error("XdmfSidecar::add: this sidecar is a time series (add_step)");
  add_views(h5, fields);
  steps_.push_back({std::nullopt, fields});
  return *this;
}

XdmfSidecar& XdmfSidecar::add_written(const std::vector<XdmfField>& fields) {
  if (!steps_.empty() && steps_.front().time)
    throw std::logic_error("XdmfSidecar::add_written: this sidecar is a time series (add_step)");
  steps_.push_back({std::nullopt, fields});
  return *this;
}

XdmfSidecar& XdmfSidecar::add_step(H5Writer& h5, double time, const std::vector<XdmfField>& fields) {
  if (!steps_.empty() && !steps_.front().time)
    throw std::logic_error("XdmfSidecar::add_step: this sidecar holds one grid (add)");
  add_views(h5, fields);
  steps_.push_back({time, fields});
  return *this;
}

void XdmfSidecar::write(const std::filesystem::path& xdmf_path, const std::filesystem::path& h5_file,
                        const std::string& time_name, const std::string& time_unit) const {
  const auto base = xdmf_path.parent_path().empty() ? std::filesystem::path(".") : xdmf_path.parent_path();
  const auto h5 = escaped(std::filesystem::proximate(h5_file, base).string());
  // VTK's image data runs x fastest and XDMF lists dimensions slowest first:
  // one plane (z), ny rows (y), nx points along x. Origin and spacing follow
  // the same (z, y, x) order; the spacing along z is unused (one plane).
  const std::string dims = fmt::format("1 {} {}", grid_.ny, grid_.nx);
  auto grid_xml = [&](const Step& step, const std::string& name, const std::string& indent) {
    std::string xml = fmt::format(
        "{0}<Grid Name=\"{1}\" GridType=\"Uniform\">\n"
        "{0} <Topology TopologyType=\"3DCoRectMesh\" Dimensions=\"{2}\"/>\n"
        "{0} <Geometry GeometryType=\"ORIGIN_DXDYDZ\">\n"
        "{0}  <DataItem Format=\"XML\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"3\">0 {3:.17g} {4:.17g}</DataItem>\n"
        "{0}  <DataItem Format=\"XML\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"3\">{6:.17g} {5:.17g} {6:.17g}</DataItem>\n"
        "{0} </Geometry>\n",
        indent, escaped(name), dims, origin_[1], origin_[0], grid_.dy(), grid_.dx());
    if (step.time) xml += fmt::format("{} <Time Value=\"{:.17g}\"/>\n", indent, *step.time);
    for (const auto& f : step.fields)
      xml += fmt::format(
          "{0} <Attribute Name=\"{1}\" AttributeType=\"Scalar\" Center=\"Node\">\n"
          "{0}  <DataItem Format=\"HDF\" NumberType=\"Float\" Precision=\"8\" Dimensions=\"{2}\">{3}:{4}</DataItem>\n"
          "{0} </Attribute>\n",
          indent, escaped(f.name), dims, h5, escaped(xdmf_view(f.dataset)));
    return xml + indent + "</Grid>\n";
  };
  std::string xml = "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n";
  const bool temporal = !steps_.empty() && steps_.front().time.has_value();
  if (!temporal) {
    // One grid with every field added.
    Step all;
    for (const auto& s : steps_) all.fields.insert(all.fields.end(), s.fields.begin(), s.fields.end());
    xml += grid_xml(all, "surface", "  ");
  } else {
    xml += "  <Grid Name=\"snapshots\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
    for (const auto& s : steps_)
      xml += grid_xml(s, fmt::format("{} = {:.6g}{}{}", time_name, s.time.value_or(0.0), time_unit.empty() ? "" : " ",
                                     time_unit),
                      "   ");
    xml += "  </Grid>\n";
  }
  xml += " </Domain>\n</Xdmf>\n";
  write_file_atomically(xdmf_path, xml);
}

}  // namespace wearscale
