// ISO 25178-71 Surface Data Files (SDF, after EUR 15178N): "aISO-1.0"
// (ASCII: "Key = value" header lines, a "*" line, NumProfiles rows of
// NumPoints values, BAD for a missing point, a "*" line, an optional
// trailer) or "bISO-1.0" (binary: an 81-byte little-endian header, then the
// values). Heights are value · Zscale and the steps Xscale, Yscale, all in
// metres; integer data of 16 and 32 bits mark missing points with the
// type's extreme (the minimum of signed, the maximum of unsigned types),
// floating-point data with NaN.
#include <charconv>
#include <cmath>
#include <limits>
#include <map>

#include <fmt/format.h>

#include "topography_formats.hpp"

namespace wearscale::bem::formats {

namespace {

struct Header {
  std::size_t points = 0, profiles = 0;  // NumPoints (along x), NumProfiles (along y)
  double xscale = 0.0, yscale = 0.0, zscale = 0.0;
  int compression = 0, data_type = 0;
};

void check(const Header& h, const std::string& where) {
  if (h.compression != 0) refuse(where, fmt::format("Compression = {} is not read; allowed: 0", h.compression));
  if (h.data_type < 0 || h.data_type > 7)
    refuse(where, fmt::format("DataType = {} is not an SDF data type; allowed: 0 to 7", h.data_type));
  for (const auto& [name, v] : {std::pair{"Xscale", h.xscale}, std::pair{"Yscale", h.yscale}})
    if (!(std::isfinite(v) && v > 0.0)) refuse(where, fmt::format("{} = {}; allowed: > 0 (metres per point)", name, v));
  if (!(std::isfinite(h.zscale) && h.zscale != 0.0))
    refuse(where, fmt::format("Zscale = {}; allowed: finite, not 0 (metres per unit)", h.zscale));
}

// The value marking a missing point of an integer type, if it has one.
std::optional<double> missing_marker(int type) {
  switch (type) {
    case 1: return std::numeric_limits<std::uint16_t>::max();
    case 2: return std::numeric_limits<std::uint32_t>::max();
    case 5: return std::numeric_limits<std::int16_t>::min();
    case 6: return std::numeric_limits<std::int32_t>::min();
    default: return std::nullopt;
  }
}

RawTopography grid(const Header& h, const std::string& where, const TopographyOptions& o) {
  RawTopography raw;
  raw.where = where;
  raw.format = "ISO 25178-71 SDF";
  raw.allocate(h.points, h.profiles, o.max_points);
  raw.lx = static_cast<double>(h.points) * h.xscale;
  raw.ly = static_cast<double>(h.profiles) * h.yscale;
  return raw;
}

void put(RawTopography& raw, const Header& h, std::size_t c, std::size_t r, double v, bool bad) {
  const auto marker = missing_marker(h.data_type);
  if (bad || std::isnan(v) || (marker && v == *marker)) {
    if (raw.missing.empty()) raw.first_missing = fmt::format("point {} of profile {}", c, r);
    raw.mark_missing(c, r);
    return;
  }
  raw.at(c, r) = v * h.zscale;
}

RawTopography parse_binary(std::string_view bytes, const std::string& where, const TopographyOptions& o) {
  Bytes b(bytes, where);
  b.skip(8 + 10 + 12 + 12, "the header");
  Header h;
  h.points = b.u16("NumPoints");
  h.profiles = b.u16("NumProfiles");
  h.xscale = b.f64("Xscale");
  h.yscale = b.f64("Yscale");
  h.zscale = b.f64("Zscale");
  b.f64("Zresolution");
  h.compression = b.u8("Compression");
  h.data_type = b.u8("DataType");
  b.u8("CheckType");
  check(h, where);
  constexpr std::size_t sizes[] = {1, 2, 4, 4, 1, 2, 4, 8};
  const auto need = product(product(h.points, h.profiles).value_or(0), sizes[h.data_type]);
  if (!need || *need > bytes.size() - b.pos())
    refuse(where, fmt::format("the file ends before its {} × {} values ({} bytes after the header, {} needed)",
                              h.points, h.profiles, bytes.size() - b.pos(), need.value_or(0)));
  RawTopography raw = grid(h, where, o);
  for (std::size_t r = 0; r < h.profiles; ++r)
    for (std::size_t c = 0; c < h.points; ++c) {
      double v = 0.0;
      switch (h.data_type) {
        case 0: v = b.u8("the data"); break;
        case 1: v = b.u16("the data"); break;
        case 2: v = b.u32("the data"); break;
        case 3: v = b.f32("the data"); break;
        case 4: v = static_cast<std::int8_t>(b.u8("the data")); break;
        case 5: v = b.i16("the data"); break;
        case 6: v = b.i32("the data"); break;
        default: v = b.f64("the data"); break;
      }
      put(raw, h, c, r, v, false);
    }
  return raw;
}

RawTopography parse_ascii(std::string_view text, const std::string& where, const TopographyOptions& o) {
  std::map<std::string, std::string, std::less<>> keys;
  std::size_t p = text.find('\n');
  std::size_t line_no = 1;
  auto trim = [](std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
  };
  bool data_started = false;
  while (p != std::string_view::npos && p < text.size()) {
    const std::size_t start = p + 1;
    const std::size_t end = std::min(text.find('\n', start), text.size());
    const auto line = trim(text.substr(start, end - start));
    p = end;
    ++line_no;
    if (line == "*") {
      data_started = true;
      break;
    }
    if (line.empty() || line.front() == ';') continue;
    const auto eq = line.find('=');
    if (eq == std::string_view::npos) refuse(where, fmt::format("line {}: '{}' is not 'Key = value'", line_no, line));
    keys[std::string(trim(line.substr(0, eq)))] = std::string(trim(line.substr(eq + 1)));
  }
  if (!data_started) refuse(where, "the header has no end (a line with '*')");
  auto number = [&](const char* key) {
    const auto it = keys.find(key);
    if (it == keys.end()) refuse(where, fmt::format("the header has no {}", key));
    double v = 0.0;
    const auto& s = it->second;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size() || !std::isfinite(v))
      refuse(where, fmt::format("{} = '{}' is not a number", key, s));
    return v;
  };
  auto count = [&](const char* key) {
    const double v = number(key);
    if (!(v >= 1.0 && v <= 1e9 && std::floor(v) == v))
      refuse(where, fmt::format("{} = {} is not a number of points; allowed: a positive integer", key, v));
    return static_cast<std::size_t>(v);
  };
  Header h;
  h.points = count("NumPoints");
  h.profiles = count("NumProfiles");
  h.xscale = number("Xscale");
  h.yscale = number("Yscale");
  h.zscale = number("Zscale");
  // A format code must be an integer before it is one; check() tests its allowed values.
  auto code = [&](const char* key, const char* allowed) {
    const double v = number(key);
    if (!(std::floor(v) == v && std::abs(v) <= 1e6))
      refuse(where, fmt::format("{} = {} is not an integer; allowed: {}", key, v, allowed));
    return static_cast<int>(v);
  };
  h.compression = keys.contains("Compression") ? code("Compression", "0") : 0;
  h.data_type = code("DataType", "0 to 7");
  check(h, where);
  // Every value takes at least two characters: a file too short is refused before anything is allocated.
  const auto values = product(h.points, h.profiles);
  if (!values || *values > (text.size() - p) / 2 + 1)
    refuse(where, fmt::format("the file is too short for its {} × {} values", h.points, h.profiles));
  RawTopography raw = grid(h, where, o);
  std::size_t k = 0;
  const std::size_t n = raw.height.size();
  std::size_t q = p + 1;
  while (k < n) {
    while (q < text.size() && std::isspace(static_cast<unsigned char>(text[q]))) ++q;
    if (q >= text.size() || text[q] == '*')
      refuse(where, fmt::format("the data end after {} of {} values (NumPoints × NumProfiles)", k, n));
    std::size_t e = q;
    while (e < text.size() && !std::isspace(static_cast<unsigned char>(text[e]))) ++e;
    const auto token = text.substr(q, e - q);
    double v = 0.0;
    const bool bad = token == "BAD";
    if (!bad) {
      const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), v);
      if (ec != std::errc() || ptr != token.data() + token.size())
        refuse(where, fmt::format("value {} ('{}') is not a number (nor BAD)", k + 1, token));
      if (std::isinf(v)) refuse(where, fmt::format("value {} ('{}') is not finite", k + 1, token));
    }
    put(raw, h, k % h.points, k / h.points, v, bad);
    ++k;
    q = e;
  }
  return raw;
}

}  // namespace

RawTopography parse_sdf(std::string_view bytes, const std::string& where, const TopographyOptions& o) {
  return bytes.starts_with("bISO-1.0") ? parse_binary(bytes, where, o) : parse_ascii(bytes, where, o);
}

}  // namespace wearscale::bem::formats
