// Gwyddion's files: the native .gwy (a tree of serialised objects, the
// channels as GwyDataField under "/N/data", their masks under "/N/mask")
// and the Gwyddion Simple Field .gsf (a "Key = Value" text header, NUL
// padding to a multiple of 4, float32 data). Both little-endian, rows along
// y with x fastest, sizes and units in SI base units.
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "topography_formats.hpp"
#include "wearscale/core/log.hpp"

namespace wearscale::bem::formats {

namespace {

// Metres per unit of a unit string a file gives for lengths; an empty one
// is taken as metres (Gwyddion's base unit), anything else is refused.
double length_unit(const std::string& unit, const std::string& where, const char* what) {
  if (unit.empty()) {
    log::warn("{}: no unit for the {}: taken as metres", where, what);
    return 1.0;
  }
  const auto m = metres_per(unit);
  if (!m) refuse(where, fmt::format("the {} are in '{}', not a unit of length: not a topography", what, unit));
  return *m;
}

// ------------------------------------------------------------------ GWY ---

struct DataField {
  std::int64_t xres = 0, yres = 0;
  double xreal = 0.0, yreal = 0.0;
  std::string unit_xy, unit_z;
  bool has_xreal = false, has_yreal = false;
  std::string_view data;  ///< xres·yres little-endian doubles
  std::size_t count = 0;
};

class GwyParser {
 public:
  GwyParser(std::string_view bytes, const std::string& where) : b_(bytes, where) {}

  /// The top-level GwyContainer: every component of type 'o' named
  /// "/N/data" or "/N/mask" parsed as a GwyDataField, titles kept.
  void parse() {
    b_.seek(4, "the magic GWYP");
    const std::string type = b_.cstring("the top-level object's type");
    if (type != "GwyContainer") refuse(b_.where(), fmt::format("the top-level object is a {}, not a GwyContainer", type));
    const std::size_t end = object_end();
    while (b_.pos() < end) {
      const std::string name = b_.cstring("a component name");
      const char kind = static_cast<char>(b_.u8("a component type"));
      const auto channel = channel_of(name);
      if (kind == 'o' && channel && (name.ends_with("/data") || name.ends_with("/mask"))) {
        const std::string object = b_.cstring("an object type");
        const std::size_t object_stop = object_end();
        if (object == "GwyDataField") {
          DataField f = data_field(object_stop);
          (name.ends_with("/data") ? fields : masks)[*channel] = f;
        }
        b_.seek(object_stop, "an object");
      } else if (kind == 's' && channel && name.ends_with("/data/title")) {
        titles[*channel] = b_.cstring("a channel title");
      } else {
        skip(kind, 0);
      }
    }
    if (b_.pos() != end) refuse(b_.where(), "the container's components overrun its size");
  }

  std::map<long, DataField> fields, masks;
  std::map<long, std::string> titles;

 private:
  // "/12/data" → 12
  static std::optional<long> channel_of(const std::string& name) {
    if (name.size() < 3 || name[0] != '/') return std::nullopt;
    long v = 0;
    std::size_t k = 1;
    for (; k < name.size() && k < 10 && std::isdigit(static_cast<unsigned char>(name[k])); ++k) v = v * 10 + (name[k] - '0');
    if (k == 1 || k >= name.size() || name[k] != '/') return std::nullopt;
    return v;
  }

  // Reads an object's size and returns where it ends.
  std::size_t object_end() {
    const std::uint32_t size = b_.u32("an object's size");
    if (size > b_.size() - b_.pos()) refuse(b_.where(), fmt::format("an object of {} bytes runs past the end of the file", size));
    return b_.pos() + size;
  }

  void skip_object(int depth) {
    if (depth > 32) refuse(b_.where(), "objects nested more than 32 deep");
    b_.cstring("an object type");
    b_.seek(object_end(), "an object");
  }

  void skip(char kind, int depth) {
    auto items = [&](std::size_t size) {
      const std::uint32_t n = b_.u32("an array length");
      const auto bytes = product(n, size);
      if (!bytes) refuse(b_.where(), "an array too large");
      b_.skip(*bytes, "an array");
    };
    switch (kind) {
      case 'b': case 'c': b_.skip(1, "a component"); break;
      case 'i': b_.skip(4, "a component"); break;
      case 'q': case 'd': b_.skip(8, "a component"); break;
      case 's': b_.cstring("a string component"); break;
      case 'o': skip_object(depth + 1); break;
      case 'C': items(1); break;
      case 'I': items(4); break;
      case 'Q': case 'D': items(8); break;
      case 'S': {
        const std::uint32_t n = b_.u32("an array length");
        for (std::uint32_t k = 0; k < n; ++k) b_.cstring("a string of an array");
        break;
      }
      case 'O': {
        const std::uint32_t n = b_.u32("an array length");
        for (std::uint32_t k = 0; k < n; ++k) skip_object(depth + 1);
        break;
      }
      default:
        refuse(b_.where(), fmt::format("component type '{}' (byte {}) is not one of GWY's (bcidqsoCIQDSO)",
                                       kind >= 32 && kind < 127 ? std::string(1, kind) : "?", b_.pos() - 1));
    }
  }

  std::string si_unit(std::size_t stop) {
    const std::string type = b_.cstring("a unit object's type");
    const std::size_t end = object_end();
    if (end > stop) refuse(b_.where(), "a unit object runs past its data field");
    std::string unit;
    while (b_.pos() < end) {
      const std::string name = b_.cstring("a unit component");
      const char kind = static_cast<char>(b_.u8("a unit component type"));
      if (name == "unitstr" && kind == 's')
        unit = b_.cstring("a unit string");
      else
        skip(kind, 2);
    }
    if (b_.pos() != end || type != "GwySIUnit") refuse(b_.where(), "a malformed GwySIUnit");
    return unit;
  }

  DataField data_field(std::size_t stop) {
    DataField f;
    while (b_.pos() < stop) {
      const std::string name = b_.cstring("a data field component");
      const char kind = static_cast<char>(b_.u8("a data field component type"));
      if (name == "xres" && kind == 'i') f.xres = b_.i32("xres");
      else if (name == "yres" && kind == 'i') f.yres = b_.i32("yres");
      else if (name == "xreal" && kind == 'd') f.xreal = b_.f64("xreal"), f.has_xreal = true;
      else if (name == "yreal" && kind == 'd') f.yreal = b_.f64("yreal"), f.has_yreal = true;
      else if (name == "si_unit_xy" && kind == 'o') f.unit_xy = si_unit(stop);
      else if (name == "si_unit_z" && kind == 'o') f.unit_z = si_unit(stop);
      else if (name == "data" && kind == 'D') {
        f.count = b_.u32("the data length");
        const auto bytes = product(f.count, 8);
        if (!bytes) refuse(b_.where(), "the data array is too large");
        f.data = b_.take(*bytes, "the data of a channel");
      } else {
        skip(kind, 1);
      }
    }
    if (b_.pos() != stop) refuse(b_.where(), "a data field's components overrun its size");
    return f;
  }

  Bytes b_;
};

void check_field(const DataField& f, const std::string& where, const char* what) {
  if (f.xres <= 0 || f.yres <= 0)
    refuse(where, fmt::format("the {} has {} × {} points; allowed: at least 1 × 1", what, f.xres, f.yres));
  const auto n = product(static_cast<std::size_t>(f.xres), static_cast<std::size_t>(f.yres));
  if (!n || *n != f.count)
    refuse(where, fmt::format("the {} holds {} values for {} × {} points", what, f.count, f.xres, f.yres));
}

double value(const DataField& f, std::size_t k) {
  Bytes b(f.data.substr(8 * k, 8), "");
  return b.f64("");
}

}  // namespace

RawTopography parse_gwy(std::string_view bytes, const std::string& where, const TopographyOptions& o) {
  GwyParser p(bytes, where);
  p.parse();
  // The first channel (lowest number) whose values are lengths: a height.
  const DataField* height = nullptr;
  long channel = -1;
  std::string others;
  for (const auto& [id, f] : p.fields) {
    if (metres_per(f.unit_z)) {
      height = &f, channel = id;
      break;
    }
    const auto title = p.titles.find(id);
    others += fmt::format("{}{} ('{}', in {})", others.empty() ? "" : ", ", id,
                          title == p.titles.end() ? "untitled" : title->second, f.unit_z.empty() ? "no unit" : f.unit_z);
  }
  if (height == nullptr)
    refuse(where, p.fields.empty() ? std::string("no image channel (GwyDataField under /N/data)")
                                   : fmt::format("no channel of heights (values in a unit of length); channels: {}",
                                                 others));
  check_field(*height, where, "height channel");
  RawTopography raw;
  raw.where = where;
  raw.format = "Gwyddion";
  const auto nx = static_cast<std::size_t>(height->xres), ny = static_cast<std::size_t>(height->yres);
  raw.allocate(nx, ny, o.max_points);
  const double z = length_unit(height->unit_z, where, "heights");
  for (std::size_t r = 0; r < ny; ++r)
    for (std::size_t c = 0; c < nx; ++c) {
      const double v = value(*height, r * nx + c);
      raw.at(c, r) = v * z;
      if (std::isnan(v)) raw.mark_missing(c, r);
    }
  // Gwyddion's importers mark invalid points in the channel's mask.
  if (const auto m = p.masks.find(channel); m != p.masks.end()) {
    check_field(m->second, where, "mask");
    if (m->second.xres != height->xres || m->second.yres != height->yres)
      refuse(where, fmt::format("the mask has {} × {} points, the heights {} × {}", m->second.xres, m->second.yres,
                                height->xres, height->yres));
    for (std::size_t r = 0; r < ny; ++r)
      for (std::size_t c = 0; c < nx; ++c)
        if (value(m->second, r * nx + c) > 0.0) {
          if (raw.first_missing.empty()) raw.first_missing = fmt::format("column {}, row {} (masked)", c, r);
          raw.mark_missing(c, r);
        }
  }
  if (raw.first_missing.empty() && !raw.missing.empty()) raw.first_missing = "a NaN";
  const double xy = length_unit(height->unit_xy, where, "lateral sizes");
  if (height->has_xreal) raw.lx = height->xreal * xy;
  if (height->has_yreal) raw.ly = height->yreal * xy;
  return raw;
}

// ------------------------------------------------------------------ GSF ---

RawTopography parse_gsf(std::string_view bytes, const std::string& where, const TopographyOptions& o) {
  constexpr std::string_view magic = "Gwyddion Simple Field 1.0\n";
  const auto nul = bytes.find('\0', magic.size());
  if (nul == std::string_view::npos) refuse(where, "the header does not end (no NUL byte after it)");
  std::map<std::string, std::string, std::less<>> header;
  const std::string_view text = bytes.substr(magic.size(), nul - magic.size());
  std::size_t line_no = 1;
  for (std::size_t start = 0; start < text.size(); ++line_no) {
    const auto end = std::min(text.find('\n', start), text.size());
    std::string_view line = text.substr(start, end - start);
    start = end + 1;
    const auto eq = line.find('=');
    auto trim = [](std::string_view s) {
      while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
      while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
      return s;
    };
    if (trim(line).empty()) continue;
    if (eq == std::string_view::npos)
      refuse(where, fmt::format("header line {} ('{}') is not 'Name = value'", line_no + 1, trim(line)));
    header[std::string(trim(line.substr(0, eq)))] = std::string(trim(line.substr(eq + 1)));
  }
  auto number = [&](const char* key) -> std::optional<double> {
    const auto it = header.find(key);
    if (it == header.end()) return std::nullopt;
    std::size_t used = 0;
    double v = 0.0;
    try {
      v = std::stod(it->second, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || used != it->second.size() || !std::isfinite(v))
      refuse(where, fmt::format("{} = '{}' is not a number", key, it->second));
    return v;
  };
  auto resolution = [&](const char* key) {
    const auto v = number(key);
    if (!v) refuse(where, fmt::format("the header has no {} (mandatory)", key));
    if (!(*v >= 1.0 && *v <= 1e9 && std::floor(*v) == *v))
      refuse(where, fmt::format("{} = {} is not a number of points; allowed: a positive integer", key, *v));
    return static_cast<std::size_t>(*v);
  };
  const std::size_t nx = resolution("XRes"), ny = resolution("YRes");
  const std::size_t data = nul + (4 - nul % 4);  // one to four NULs align the data to 4 bytes
  const auto need = product(product(nx, ny).value_or(0), 4);
  if (!need || data > bytes.size() || *need > bytes.size() - data)
    refuse(where, fmt::format("the file ends before its {} × {} float32 values", nx, ny));
  RawTopography raw;
  raw.where = where;
  raw.format = "Gwyddion Simple Field";
  raw.allocate(nx, ny, o.max_points);
  Bytes b(bytes, where);
  b.seek(data, "the NUL padding after the header");
  const auto xy = header.contains("XYUnits") ? header["XYUnits"] : std::string();
  const auto zu = header.contains("ZUnits") ? header["ZUnits"] : std::string();
  const double z = length_unit(zu, where, "heights (ZUnits)");
  for (std::size_t r = 0; r < ny; ++r)
    for (std::size_t c = 0; c < nx; ++c) {
      const double v = b.f32("the data (XRes × YRes float32 values)");
      raw.at(c, r) = v * z;
      if (std::isnan(v)) {
        if (raw.missing.empty()) raw.first_missing = fmt::format("column {}, row {}", c, r);
        raw.mark_missing(c, r);
      }
    }
  for (const auto& [key, side] : {std::pair{"XReal", &raw.lx}, std::pair{"YReal", &raw.ly}})
    if (const auto v = number(key)) {
      if (!(*v > 0.0)) refuse(where, fmt::format("{} = {} is not a size; allowed: > 0", key, *v));
      *side = *v * length_unit(xy, where, "lateral sizes (XYUnits)");
    }
  return raw;
}

}  // namespace wearscale::bem::formats
