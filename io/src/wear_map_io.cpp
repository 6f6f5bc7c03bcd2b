#include "wearscale/io/wear_map_io.hpp"

#include <span>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/xdmf.hpp"

namespace wearscale::wear {

namespace {
// The map's points as a grid spanning the axes' ranges.
Grid2D map_grid(const WearMap& map) { return {map.x.n, map.y.n, map.x.max - map.x.min, map.y.max - map.y.min}; }

// A map-shaped field (nx × ny, y fastest).
RealField as_field(const WearMap& map, std::span<const double> values) {
  RealField f(map_grid(map));
  std::copy(values.begin(), values.end(), f.begin());
  return f;
}

std::string legend(const WearMap& map) {
  std::string s;
  for (const auto& [code, name] : map.region_names) s += fmt::format("{}{} = {}", s.empty() ? "" : ", ", code, name);
  return s;
}
}  // namespace

std::filesystem::path write_wear_map_h5(const std::filesystem::path& path, const WearMap& map,
                                        std::string_view case_toml) {
  H5Writer h5(path);
  h5.set_attribute("/", "kind", map.kind);
  if (!case_toml.empty()) h5.set_attribute("/", "case_toml", case_toml);
  h5.set_attribute("/", "title", map.title);
  for (const auto& [name, value] : map.parameters) h5.set_attribute("/", name, value);
  const auto xs = map.x.values(), ys = map.y.values();
  h5.write_series("/axes/" + map.x.name, xs);
  h5.set_attribute("/axes/" + map.x.name, "label", map.x.label);
  h5.write_series("/axes/" + map.y.name, ys);
  h5.set_attribute("/axes/" + map.y.name, "label", map.y.label);
  const std::vector<double> codes(map.region.begin(), map.region.end());
  h5.write_field("/region", as_field(map, codes));
  h5.set_attribute("/region", "codes", legend(map));
  h5.set_attribute("/region", "description", "the region of each point of the map, by its code (attribute codes)");
  h5.set_attribute("/region", "axes", fmt::format("rows: {}, columns: {}", map.x.name, map.y.name));
  for (const auto& l : map.layers) {
    h5.write_field("/ratio/" + l.name, as_field(map, l.values));
    h5.set_attribute("/ratio/" + l.name, "description", l.description);
    h5.set_attribute("/ratio/" + l.name, "axes", fmt::format("rows: {}, columns: {}", map.x.name, map.y.name));
  }
  // ParaView: the region codes and every layer; the map samples cell
  // centres, so the first node is half a cell in from (min, min).
  std::vector<XdmfField> fields = {{"/region", "region"}};
  for (const auto& l : map.layers) fields.push_back({"/ratio/" + l.name, l.name});
  XdmfSidecar sidecar(map_grid(map), {map.x.value(0), map.y.value(0)});
  sidecar.add(h5, fields);
  h5.commit();
  auto xmf = path;
  xmf.replace_extension(".xdmf");
  sidecar.write(xmf, path);
  return xmf;
}

void write_wear_map_csv(const std::filesystem::path& path, const WearMap& map) {
  const std::size_t n = map.x.n * map.y.n;
  std::vector<double> xs(n), ys(n), codes(map.region.begin(), map.region.end());
  for (std::size_t i = 0; i < map.x.n; ++i)
    for (std::size_t j = 0; j < map.y.n; ++j) {
      xs[map.index(i, j)] = map.x.value(i);
      ys[map.index(i, j)] = map.y.value(j);
    }
  std::vector<std::string> names = {map.x.name, map.y.name, "region"};
  std::vector<std::span<const double>> columns = {xs, ys, codes};
  std::vector<std::string> comments = {map.title, "region: " + legend(map)};
  for (const auto& l : map.layers) {
    names.push_back(l.name);
    columns.emplace_back(l.values);
    comments.push_back(fmt::format("{}: {}", l.name, l.description));
  }
  for (const auto& [name, value] : map.parameters) comments.push_back(fmt::format("{} = {:.17g}", name, value));
  // Every axis and layer of a wear map is a ratio (d/l, R, p/p_crit): dimensionless.
  write_csv(path, names, columns, std::vector<std::string>(names.size(), "1"), comments);
}

}  // namespace wearscale::wear
