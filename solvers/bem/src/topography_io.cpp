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

bool is_hdf5_name(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext == ".h5" || ext == ".hdf5" || ext == ".hdf";
}

}  // namespace

RealField read_topography_text(const fs::path& file, const TopographySize& size) {
  const std::string name = file.string();
  std::error_code ec;
  if (!fs::is_regular_file(file, ec)) throw InputError(fmt::format("{}: no such file", name));
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open for reading", name));
  std::stringstream content;
  content << in.rdbuf();
  return parse_topography_text(content.str(), name, size);
}

RealField parse_topography_text(std::string_view content, const std::string& name, const TopographySize& size) {
  const fs::path file = name;
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
  return h;
}

RealField read_topography_h5(const fs::path& file, const std::string& dataset, const TopographySize& size) {
  const H5Reader reader(file);
  if (!reader.exists(dataset))
    throw InputError(fmt::format("{}: no dataset '{}'; name the height dataset (e.g. --dataset /surface/height)",
                                 file.string(), dataset));
  const RealField raw = reader.read_field(dataset);
  auto attribute = [&](const char* key) -> std::optional<double> {
    try {
      return reader.number_attribute(dataset, key);
    } catch (const InputError&) {
      return std::nullopt;
    }
  };
  const std::string where = fmt::format("{}: dataset '{}'", file.string(), dataset);
  const Grid2D grid = resolve_grid(raw.rows(), raw.cols(), size, attribute("lx"), attribute("ly"), where,
                                   "the dataset has no lx/ly attributes, so pass the size");
  RealField h(grid);
  for (std::size_t i = 0; i < grid.nx; ++i)
    for (std::size_t j = 0; j < grid.ny; ++j) {
      if (!std::isfinite(raw(i, j)))
        throw InputError(fmt::format("{}: height at row {}, column {} is {}; allowed: finite heights", where, i + 1,
                                     j + 1, raw(i, j)));
      h(i, j) = raw(i, j);
    }
  return h;
}

RealField read_topography(const fs::path& file, const std::string& dataset, const TopographySize& size) {
  return is_hdf5_name(file) ? read_topography_h5(file, dataset, size) : read_topography_text(file, size);
}

fs::path write_surface(const fs::path& file, const RealField& h, const SurfaceAttributes& attributes) {
  XdmfSidecar xdmf(h.grid());
  {
    H5Writer writer(file);
    writer.write_field(default_surface_dataset, h, "m");
    for (const auto& [key, value] : attributes) writer.set_attribute(default_surface_dataset, key, value);
    writer.set_attribute("/surface", "description", "surface heights h(x_i, y_j), rows i along x, columns j along y");
    xdmf.add(writer, {{default_surface_dataset, "height"}});
    writer.commit();
  }
  fs::path sidecar = file;
  sidecar.replace_extension(".xdmf");
  xdmf.write(sidecar, file);
  return sidecar;
}

SurfaceAttributes generation_attributes(const RoughSurfaceSpec& spec) {
  return {{"hurst", spec.hurst}, {"k_l", spec.k_l}, {"k_r", spec.k_r}, {"k_s", spec.k_s},
          {"seed", static_cast<double>(spec.seed)}};
}

std::optional<double> read_surface_attribute(const fs::path& file, const std::string& dataset, const std::string& name) {
  if (!is_hdf5_name(file)) return std::nullopt;
  const H5Reader reader(file);
  if (!reader.exists(dataset)) return std::nullopt;
  try {
    return reader.number_attribute(dataset, name);
  } catch (const InputError&) {
    return std::nullopt;
  }
}

}  // namespace wearscale::bem
