// Text grids: wearscale's own (rows along x, "# lx = …" comments) and
// Gwyddion's ASCII matrix export (rows along y; "# Channel:", "# Width:",
// "# Height:", "# Value units:" in the language Gwyddion runs in).
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "topography_formats.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/units.hpp"

namespace wearscale::bem::formats {

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

enum class Parsed { Ok, Missing, NotANumber, NotFinite };

Parsed parse_number(std::string_view text, double& value) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  if (text.empty()) return Parsed::NotANumber;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range) return Parsed::NotFinite;
  if (ec != std::errc() || ptr != text.data() + text.size()) return Parsed::NotANumber;
  if (std::isnan(value)) return Parsed::Missing;
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
  // "5.000 µm" as Gwyddion writes it: a number, then a unit of length.
  text = trim(text);
  const auto blank = text.find_first_of(" \t");
  if (blank == std::string_view::npos) return std::nullopt;
  if (parse_number(trim(text.substr(0, blank)), v) != Parsed::Ok) return std::nullopt;
  const auto unit = metres_per(trim(text.substr(blank + 1)));
  if (!unit) return std::nullopt;
  return v * *unit;
}

/// "# lx = <length>" or "# ly = <length>" (case-insensitive, '=' or ':').
void read_size_comment(std::string_view comment, const std::string& file, std::size_t line, std::optional<double>& lx,
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
                                 "(\"1e-3\") or with a unit (\"877 um\")", file, line, b, value));
  (b == 'x' ? lx : ly) = *length;
}

// Gwyddion's ASCII export header, in each language Gwyddion translates it to.
struct GwyddionHeader {
  bool seen = false;
  std::optional<double> width, height, value_unit;
};
constexpr std::string_view kWidth[] = {"Width:", "Šířka:", "Breite:", "Anchura:", "Largeur :", "Larghezza:",
                                       "幅:",     "폭:",     "Largura:", "Ширина:"};
constexpr std::string_view kHeight[] = {"Height:", "Výška:", "Höhe:", "Altura:", "Hauteur :",
                                        "Altezza:", "高さ：", "높이:", "Высота:"};
constexpr std::string_view kUnits[] = {"Value units:", "Jednotky hodnot:", "Einheiten:", "Unités :",
                                       "unità valore:", "値の単位:", "값 단위:", "Unidades de valor:",
                                       "Единицы измерения:"};
constexpr std::string_view kChannel[] = {"Channel:", "Kanál:", "Kanal:", "Canal:", "Canal :", "Canale:",
                                         "チャネル：", "채널:", "Канал:"};

template <std::size_t N>
std::optional<std::string_view> field_of(std::string_view comment, const std::string_view (&keys)[N]) {
  for (const auto key : keys)
    if (comment.starts_with(key)) return trim(comment.substr(key.size()));
  return std::nullopt;
}

void read_gwyddion_comment(std::string_view comment, const std::string& file, std::size_t line, GwyddionHeader& h) {
  comment = trim(comment);
  if (field_of(comment, kChannel)) {
    h.seen = true;
    return;
  }
  auto length = [&](std::string_view value, const char* what) {
    h.seen = true;
    const auto v = parse_length(value);
    if (!v || !(*v > 0.0))
      throw InputError(fmt::format("{}: line {}: {} '{}' of the Gwyddion export is not a length; allowed: a positive "
                                   "number and a unit of length (\"5.000 µm\")", file, line, what, value));
    return v;
  };
  if (const auto w = field_of(comment, kWidth)) {
    h.width = length(*w, "width");
  } else if (const auto ht = field_of(comment, kHeight)) {
    h.height = length(*ht, "height");
  } else if (const auto u = field_of(comment, kUnits)) {
    h.seen = true;
    h.value_unit = metres_per(*u);
    if (!h.value_unit)
      throw InputError(fmt::format("{}: line {}: the values are in '{}', not a unit of length: not a topography "
                                   "(a height channel is in m)", file, line, *u));
  }
}

}  // namespace

RawTopography parse_text(std::string_view content, const std::string& where, const TopographyOptions& o) {
  content = strip_utf8_bom(content);  // as spreadsheet programs write
  RawTopography raw;
  raw.where = where;
  std::optional<double> lx, ly;
  GwyddionHeader gwyddion;
  std::vector<double> values;
  std::vector<std::size_t> missing;  // positions in `values`
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
      read_size_comment(text.substr(1), where, line_no, lx, ly);
      read_gwyddion_comment(text.substr(1), where, line_no, gwyddion);
      continue;
    }
    split(text, fields);
    if (header_allowed) {
      header_allowed = false;
      double v = 0.0;
      const bool any_number = std::any_of(fields.begin(), fields.end(),
                                          [&](std::string_view f) { return parse_number(f, v) != Parsed::NotANumber; });
      if (!any_number) continue;  // a row of column names
    }
    for (std::size_t c = 0; c < fields.size(); ++c) {
      double v = 0.0;
      switch (parse_number(fields[c], v)) {
        case Parsed::Ok: break;
        case Parsed::Missing:
          if (missing.empty()) raw.first_missing = fmt::format("line {}, column {}", line_no, c + 1);
          missing.push_back(values.size());
          break;
        case Parsed::NotANumber:
          throw InputError(fmt::format("{}: line {}, column {}: {} is not a number", where, line_no, c + 1,
                                       fields[c].empty() ? std::string("an empty value")
                                                         : fmt::format("'{}'", fields[c])));
        case Parsed::NotFinite:
          throw InputError(fmt::format("{}: line {}, column {}: '{}' is not a finite number (infinity or out of "
                                       "range); allowed: finite heights, or nan for a missing point",
                                       where, line_no, c + 1, fields[c]));
      }
      values.push_back(v);
    }
    if (rows == 0) {
      cols = fields.size();
      first_row_line = line_no;
    } else if (fields.size() != cols) {
      throw InputError(fmt::format("{}: line {}: {} values, but the first row (line {}) has {}; every row of the "
                                   "grid must have the same number of columns",
                                   where, line_no, fields.size(), first_row_line, cols));
    }
    ++rows;
  }
  if (rows == 0) throw InputError(fmt::format("{}: no height data (the file is empty or holds only comments)", where));
  if (!gwyddion.seen) {
    raw.format = "text grid";
    raw.allocate(rows, cols, o.max_points);
    std::copy(values.begin(), values.end(), raw.height.begin());
    for (const auto k : missing) raw.mark_missing(k / cols, k % cols);
    raw.lx = lx, raw.ly = ly;
    return raw;
  }
  // Gwyddion: a line per y, x fastest; values in the value unit.
  raw.format = "Gwyddion ASCII export";
  raw.allocate(cols, rows, o.max_points);
  const double unit = gwyddion.value_unit.value_or(1.0);
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < cols; ++c) raw.at(c, r) = values[r * cols + c] * unit;
  for (const auto k : missing) raw.mark_missing(k % cols, k / cols);
  raw.lx = gwyddion.width ? gwyddion.width : lx;
  raw.ly = gwyddion.height ? gwyddion.height : ly;
  return raw;
}

}  // namespace wearscale::bem::formats
