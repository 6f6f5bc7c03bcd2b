#include "wear_map_output.hpp"

#include <fmt/format.h>

#include "wearscale/core/output_set.hpp"
#include "wearscale/io/wear_map_io.hpp"

namespace wearscale::studies {

namespace fs = std::filesystem;

std::pair<double, double> read_range(const Config& cfg, const std::string& key, std::pair<double, double> fallback,
                                     const Range& element, const std::string& what) {
  if (!cfg.has(key)) {
    cfg.mark_used(key);
    return fallback;
  }
  const auto v = cfg.numbers(key, element);
  if (v.size() != 2 || !(v[0] < v[1]))
    throw cfg.error(key, "not a range [MIN, MAX] with MIN < MAX",
                    fmt::format("[MIN, MAX] of {} with MIN < MAX, each {}", what, element.describe()));
  return {v[0], v[1]};
}

wear::MapAxis read_axis(const Config& cfg, const std::string& key, wear::MapAxis axis, std::size_t n,
                        const Range& element) {
  const auto [min, max] = read_range(cfg, key, {axis.min, axis.max}, element, axis.label);
  axis.min = min, axis.max = max, axis.n = n;
  return axis;
}

void record(Config& cfg, const std::string& key, const std::string& toml_value) {
  cfg.override_value(fmt::format("{}={}", key, toml_value));
}

std::string toml_number(double v) { return fmt::format("{}", v); }

std::string toml_range(std::pair<double, double> r) {
  return fmt::format("[{}, {}]", toml_number(r.first), toml_number(r.second));
}

std::string spaced(std::string name) {
  for (auto& ch : name)
    if (ch == '_') ch = ' ';
  return name;
}

std::string heat_map_script(const wear::WearMap& map, const std::string& title, const fs::path& csv,
                            const std::vector<std::string>& colours) {
  std::string tics;
  for (const auto& [code, name] : map.region_names)
    tics += fmt::format("{}'{}' {}", tics.empty() ? "" : ", ", spaced(name), code);
  std::string palette;
  for (std::size_t k = 0; k < colours.size(); ++k)
    palette += fmt::format("{}{} '{}'", k ? ", " : "", map.region_names[k].first, colours[k]);
  const int lo = map.region_names.front().first, hi = map.region_names.back().first;
  return fmt::format(
      "set datafile separator ','\nset title \"{}\"\nset xlabel '{}'\nset ylabel '{}'\nset rmargin 17\n"
      "set xrange [{}:{}]\nset yrange [{}:{}]\nset palette defined ({})\nset palette maxcolors {}\n"
      "set cbrange [{}:{}]\nset cbtics ({})\nset key top left box opaque\nset samples 1000\n"
      "plot '{}' skip 1 using 1:2:3 with image notitle",
      title, map.x.label, map.y.label, map.x.min, map.x.max, map.y.min, map.y.max, palette, colours.size(), lo - 0.5,
      hi + 0.5, tics, csv.string());
}

void publish_analytic_map(const Config& cfg, coupling::RunContext& context, const wear::WearMap& map,
                          const std::function<std::optional<fs::path>(const fs::path&, const fs::path&)>& plot) {
  const fs::path& out = context.output_dir();
  const std::string stem = fmt::format("wearmap_{}", map.kind);
  const fs::path h5 = out / (stem + ".h5"), csv = out / (stem + ".csv"), png = out / (stem + ".png");
  const fs::path xmf = wear::write_wear_map_h5(h5, map, cfg.to_toml());
  wear::write_wear_map_csv(csv, map);
  for (const auto& f : {h5, xmf, csv}) context.add_file(f);
  if (const auto p = plot(OutputSet::readable(csv), png)) context.add_file(*p);
  const double total = static_cast<double>(map.region.size());
  for (const auto& [code, name] : map.region_names)
    context.report("fraction_" + name, static_cast<double>(map.count(code)) / total, "1",
                   fmt::format("share of the map in region {} ({})", code, name));
}

}  // namespace wearscale::studies
