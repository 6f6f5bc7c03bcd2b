#include "wear_map_output.hpp"

#include <fmt/format.h>

#include "wearscale/io/wear_map_io.hpp"

namespace wearscale::studies {

namespace fs = std::filesystem;

wear::MapAxis axis_over(wear::MapAxis axis, std::pair<double, double> range, std::size_t n) {
  axis.min = range.first, axis.max = range.second, axis.n = n;
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

coupling::Figure heat_map_figure(const wear::WearMap& map, const std::string& title, const std::string& csv,
                                 const std::vector<std::string>& colours, const std::string& lines) {
  // The regions' names, codes and colours and the axes' labels are
  // wearscale's (the map's kind); the ranges, from the case, are texts.
  std::string tics;
  for (const auto& [code, name] : map.region_names)
    tics += fmt::format("{}\"{}\" {}", tics.empty() ? "" : ", ", spaced(name), code);
  std::string palette;
  for (std::size_t k = 0; k < colours.size(); ++k)
    palette += fmt::format("{}{} \"{}\"", k ? ", " : "", map.region_names[k].first, colours[k]);
  const int lo = map.region_names.front().first, hi = map.region_names.back().first;
  coupling::Figure f{fmt::format("wearmap_{}", map.kind), "", {}, {csv}};
  f.add("title", title);
  f.add("table", csv);
  f.add("x min", map.x.min);
  f.add("x max", map.x.max);
  f.add("y min", map.y.min);
  f.add("y max", map.y.max);
  f.script = fmt::format(
      "do for [FORMAT in \"png pdf\"] {{\n"
      "if (FORMAT eq \"png\") {{ set terminal pngcairo size 1000,760 font \"sans,11\" }} "
      "else {{ set terminal pdfcairo size 7in,5.32in font \"sans,9\" }}\n"
      "set output name.\".\".FORMAT\n"
      "set title given_text(1)\nset xlabel \"{}\"\nset ylabel \"{}\"\nset rmargin 17\n"
      "set xrange [given_number(3):given_number(4)]\nset yrange [given_number(5):given_number(6)]\nset palette defined ({})\n"
      "set palette maxcolors {}\nset cbrange [{}:{}]\nset cbtics ({})\nset key top left box opaque\n"
      "set samples 1000\n"
      "plot given_text(2) using 1:2:3 with image notitle{}\n"
      "unset output\n}}\n",
      map.x.label, map.y.label, palette, colours.size(), lo - 0.5, hi + 0.5, tics, lines);
  return f;
}

void publish_analytic_map(const Config& cfg, coupling::RunContext& context, const wear::WearMap& map,
                          const std::function<coupling::Figure(const std::string& csv)>& figure) {
  const fs::path& out = context.output_dir();
  const std::string stem = fmt::format("wearmap_{}", map.kind);
  const fs::path h5 = out / (stem + ".h5"), csv = out / (stem + ".csv");
  const fs::path xmf = wear::write_wear_map_h5(h5, map, cfg.to_toml());
  wear::write_wear_map_csv(csv, map);
  for (const auto& f : {h5, xmf, csv}) context.add_file(f);
  context.add_figure(figure(csv.filename().string()));
  const double total = static_cast<double>(map.region.size());
  for (const auto& [code, name] : map.region_names)
    context.report("fraction_" + name, static_cast<double>(map.count(code)) / total, "1",
                   fmt::format("share of the map in region {} ({})", code, name));
}

}  // namespace wearscale::studies
