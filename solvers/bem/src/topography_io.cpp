#include "wearscale/bem/topography_io.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/hdf5_file.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/core/xdmf.hpp"

namespace wearscale::bem {

namespace fs = std::filesystem;

namespace {

bool is_space(char c) { return c == ' ' || c == '\t'; }
bool is_separator(char c) { return c == ',' || c == ';'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (is_space(s.front()) || s.front() == '\r')) s.remove_prefix(1);
  while (!s.empty() && (is_space(s.back()) || s.back() == '\r')) s.remove_suffix(1);
  return s;
}

/// Splits a data line into values: runs of blanks separate, and so does one
/// comma or semicolon with blanks around it. Two hard separators in a row, or
/// one at the end of the line, leave an empty value.
void split(std::string_view s, std::vector<std::string_view>& out) {
  out.clear();
  std::size_t p = 0;
  const std::size_t n = s.size();
  auto skip_blanks = [&] { while (p < n && is_space(s[p])) ++p; };
  skip_blanks();
  if (p == n) return;
  for (;;) {
    const std::size_t start = p;
    while (p < n && !is_space(s[p]) && !is_separator(s[p])) ++p;
    out.push_back(s.substr(start, p - start));
    skip_blanks();
    if (p == n) return;
    if (is_separator(s[p])) {
      ++p;
      skip_blanks();
      if (p == n) {
        out.emplace_back();
        return;
      }
    }
  }
}

enum class Parsed { Ok, NotANumber, NotFinite };

Parsed parse_number(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return Parsed::NotANumber;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) return Parsed::NotFinite;
  if (ec != std::errc() || ptr != text.data() + text.size()) return Parsed::NotANumber;
  return std::isfinite(value) ? Parsed::Ok : Parsed::NotFinite;
}

/// A length in metres from "1e-3" or "877 um"; nullopt if it is neither.
std::optional<double> parse_length(std::string_view text) {
  double v = 0.0;
  if (parse_number(text, v) == Parsed::Ok) return v;
  try {
    const auto q = units::parse_quantity(text);
    if (q.dimension == units::length && std::isfinite(q.value)) return q.value;
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

/// "# lx = <length>" or "# ly = <length>" (case-insensitive, '=' or ':').
void read_size_comment(std::string_view comment, const fs::path& file, std::size_t line, std::optional<double>& lx,
                       std::optional<double>& ly) {
  comment = trim(comment);
  if (comment.size() < 2) return;
  const char a = static_cast<char>(std::tolower(static_cast<unsigned char>(comment[0])));
  const char b = static_cast<char>(std::tolower(static_cast<unsigned char>(comment[1])));
  if (a != 'l' || (b != 'x' && b != 'y')) return;
  std::string_view rest = trim(comment.substr(2));
  if (rest.empty() || (rest.front() != '=' && rest.front() != ':')) return;
  const std::string_view value = trim(rest.substr(1));
  const auto length = parse_length(value);
  if (!length || !(*length > 0.0))
    throw InputError(fmt::format("{}: line {}: l{} = '{}' is not a length; allowed: a positive length in metres "
                                 "(\"1e-3\") or with a unit (\"877 um\")", file.string(), line, b, value));
  (b == 'x' ? lx : ly) = *length;
}

/// Sizes from the caller first, then from the file; one missing side follows
/// from square pixels.
Grid2D resolve_grid(std::size_t nx, std::size_t ny, const TopographySize& given, std::optional<double> lx,
                    std::optional<double> ly, const std::string& where, const std::string& how) {
  if (given.lx) lx = given.lx;
  if (given.ly) ly = given.ly;
  if (!lx && !ly)
    throw InputError(fmt::format("{}: the size of the topography is not given; {}", where, how));
  const double rx = static_cast<double>(nx), ry = static_cast<double>(ny);
  if (!lx) lx = *ly * rx / ry;
  if (!ly) ly = *lx * ry / rx;
  for (const auto& [name, v] : {std::pair{"lx", *lx}, std::pair{"ly", *ly}})
    if (!(std::isfinite(v) && v > 0.0))
      throw InputError(fmt::format("{}: size {} = {:g} m is not allowed; allowed: > 0 m", where, name, v));
  return Grid2D(nx, ny, *lx, *ly);
}

// Heights spanning more than a thousand times the surface's side are not a
// surface (slopes beyond 10^3): most often heights in nm beside sizes in m.
void check_height_span(const RealField& h, const std::string& where) {
  double lo = h[0], hi = h[0];
  for (double v : h) lo = std::min(lo, v), hi = std::max(hi, v);
  const double side = std::max(h.grid().lx, h.grid().ly);
  if (!(hi - lo <= 1e3 * side))
    throw InputError(fmt::format("{}: heights from {:g} to {:g} m on a {:g} m × {:g} m surface (peak to valley {:g} "
                                 "times its side): are heights and sizes in the same unit? allowed: a peak-to-valley "
                                 "height of at most 1000 times the longer side",
                                 where, lo, hi, h.grid().lx, h.grid().ly, (hi - lo) / side));
}

bool is_hdf5_name(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".h5" || ext == ".hdf5" || ext == ".hdf";
}

}  // namespace

RealField read_topography_text(const fs::path& file, const TopographySize& size) {
  // The text, then up to one height per two bytes of it: about five times the file in memory.
  const double budget = memory_limit().bytes / 6.0;
  return parse_topography_text(
      read_text_file(file, "topography file", static_cast<std::uintmax_t>(std::min(budget, 1e18))), file.string(), size);
}

RealField parse_topography_text(std::string_view content, const std::string& name, const TopographySize& size) {
  const fs::path file = name;
  content = strip_utf8_bom(content);
  std::optional<double> lx, ly;
  std::vector<double> values;
  std::vector<std::string_view> fields;
  std::size_t rows = 0, cols = 0, first_row_line = 0, line_no = 0;
  bool header_allowed = true;
  for (std::size_t start = 0; start < content.size();) {
    const std::size_t end = std::min(content.find('\n', start), content.size());
    const std::string_view line = content.substr(start, end - start);
    start = end + 1;
    ++line_no;
    const std::string_view text = trim(line);
    if (text.empty()) continue;
    if (text.front() == '#') {
      read_size_comment(text.substr(1), file, line_no, lx, ly);
      continue;
    }
    split(text, fields);
    if (header_allowed) {
      header_allowed = false;
      double v = 0.0;
      const bool any_number =
          std::any_of(fields.begin(), fields.end(), [&](std::string_view f) { return parse_number(f, v) != Parsed::NotANumber; });
      if (!any_number) continue;  // a row of column names
    }
    for (std::size_t c = 0; c < fields.size(); ++c) {
      double v = 0.0;
      switch (parse_number(fields[c], v)) {
        case Parsed::Ok: break;
        case Parsed::NotANumber:
          throw InputError(fmt::format("{}: line {}, column {}: {} is not a number", name, line_no, c + 1,
                                       fields[c].empty() ? std::string("an empty value")
                                                         : fmt::format("'{}'", fields[c])));
        case Parsed::NotFinite:
          throw InputError(fmt::format("{}: line {}, column {}: '{}' is not a finite number (NaN, infinity or out of "
                                       "range); allowed: finite heights",
                                       name, line_no, c + 1, fields[c]));
      }
      values.push_back(v);
    }
    if (rows == 0) {
      cols = fields.size();
      first_row_line = line_no;
    } else if (fields.size() != cols) {
      throw InputError(fmt::format("{}: line {}: {} values, but the first row (line {}) has {}; every row of the "
                                   "grid must have the same number of columns",
                                   name, line_no, fields.size(), first_row_line, cols));
    }
    ++rows;
  }
  if (rows == 0) throw InputError(fmt::format("{}: no height data (the file is empty or holds only comments)", name));
  const Grid2D grid = resolve_grid(rows, cols, size, lx, ly, name,
                                   "add a '# lx = <length>' comment (and '# ly = ...') or pass the size");
  RealField h(grid);
  std::copy(values.begin(), values.end(), h.begin());
  check_height_span(h, name);
  return h;
}

RealField read_topography_h5(const fs::path& file, const std::string& dataset, const TopographySize& size) {
  return H5Reader::guarded(file, [&](const H5Reader& r) { return read_topography_h5(r, dataset, size); });
}

RealField read_topography_h5(const H5Reader& reader, const std::string& dataset, const TopographySize& size) {
  if (!reader.exists(dataset))
    throw InputError(fmt::format("{}: no dataset '{}'; name the height dataset (e.g. --dataset /surface/height)",
                                 reader.name(), dataset));
  const std::string where = fmt::format("{}: dataset '{}'", reader.name(), dataset);
  // Sizes in attributes: one number each, or none (a malformed one is an error, not ignored).
  const auto lx = reader.number_attribute_if(dataset, "lx"), ly = reader.number_attribute_if(dataset, "ly");
  const auto shape = reader.shape(dataset);
  if (shape.size() != 2 || shape[0] < 1 || shape[1] < 1)
    throw InputError(fmt::format("{}: not a 2D height grid ({} dimensions)", where, shape.size()));
  require_memory(2.0 * 8.0 * static_cast<double>(shape[0]) * static_cast<double>(shape[1]),
                 fmt::format("{} ({} × {} heights)", where, shape[0], shape[1]));
  const Grid2D grid = resolve_grid(shape[0], shape[1], size, lx, ly, where,
                                   "the dataset has no lx/ly attributes, so pass the size");
  const std::vector<double> raw = reader.read_series(dataset);
  RealField h(grid);
  for (std::size_t k = 0; k < raw.size(); ++k) {
    if (!std::isfinite(raw[k]))
      throw InputError(fmt::format("{}: height at row {}, column {} is {}; allowed: finite heights", where,
                                   k / grid.ny + 1, k % grid.ny + 1, raw[k]));
    h[k] = raw[k];
  }
  check_height_span(h, where);
  return h;
}

RealField read_topography(const fs::path& file, const std::string& dataset, const TopographySize& size) {
  return is_hdf5_name(file) ? read_topography_h5(file, dataset, size) : read_topography_text(file, size);
}

fs::path write_surface(const fs::path& file, const RealField& h, const SurfaceAttributes& attributes) {
  fs::path sidecar = file;
  sidecar.replace_extension(".xdmf");
  {
    H5Writer writer(file);
    writer.write_field(default_surface_dataset, h, "m");
    for (const auto& [key, value] : attributes) writer.set_attribute(default_surface_dataset, key, value);
    writer.set_attribute("/surface", "description", "surface heights h(x_i, y_j), rows i along x, columns j along y");
    // The pair goes in sidecar last: an old sidecar never describes a new file.
    std::error_code ec;
    fs::remove(sidecar, ec);
    writer.commit();
  }
  write_xdmf(sidecar, file, h.grid(), {{default_surface_dataset, "height"}});
  return sidecar;
}

SurfaceAttributes generation_attributes(const RoughSurfaceSpec& spec) {
  return {{"hurst", spec.hurst}, {"k_l", spec.k_l}, {"k_r", spec.k_r}, {"k_s", spec.k_s},
          {"seed", static_cast<double>(spec.seed)}};
}

std::optional<double> read_surface_attribute(const fs::path& file, const std::string& dataset, const std::string& name) {
  if (!is_hdf5_name(file)) return std::nullopt;
  return H5Reader::guarded(file, [&](const H5Reader& reader) -> std::optional<double> {
    if (!reader.exists(dataset)) return std::nullopt;
    return reader.number_attribute_if(dataset, name);
  });
}

}  // namespace wearscale::bem
