#include "wearscale/io/csv.hpp"

#include <cctype>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/version.hpp"

namespace wearscale {

namespace {
std::string quoted(const std::string& cell) {
  if (cell.find_first_of(",\"\n\r#") == std::string::npos && cell.find_first_not_of(' ') == 0) return cell;
  std::string out = "\"";
  for (char c : cell) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

// "m^-1" → "per_m", "m^3" → "m3", "kg" → "kg": one factor of a unit as a word.
std::string factor_word(std::string factor, bool denominator) {
  const auto caret = factor.find('^');
  std::string symbol = factor.substr(0, caret), power = caret == std::string::npos ? "" : factor.substr(caret + 1);
  if (power.starts_with("-")) {
    denominator = !denominator;
    power.erase(0, 1);
  }
  if (power == "1") power.clear();
  return (denominator ? "per_" : "") + symbol + power;
}

// A number as pandas writes a float64 column, so that a column reads back as
// floats whatever its values: "0.0", "3126.0", "1.5e-06", "nan", "inf"; a
// negative zero as "0.0", a NaN of either sign as "nan". 10 significant digits.
std::string number_cell(double v) {
  if (v == 0.0) return "0.0";
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0.0 ? "inf" : "-inf";
  std::string text = fmt::format("{:.10g}", v);
  if (text.find_first_of(".e") == std::string::npos) text += ".0";
  return text;
}

std::size_t row_count(const std::vector<std::string>* labels, const std::vector<std::span<const double>>& columns) {
  return labels ? labels->size() : columns.empty() ? 0 : columns[0].size();
}

std::string table_text(const std::vector<std::string>* labels, const std::vector<std::string>& names,
                       const std::vector<std::span<const double>>& columns) {
  if (names.size() != columns.size() + (labels ? 1 : 0))
    throw std::invalid_argument("write_csv: names and columns differ in count");
  const std::size_t rows = row_count(labels, columns);
  for (const auto& c : columns)
    if (c.size() != rows) throw std::invalid_argument("write_csv: columns differ in length");
  std::string text;
  for (std::size_t k = 0; k < names.size(); ++k) text += (k ? "," : "") + quoted(names[k]);
  text += '\n';
  for (std::size_t r = 0; r < rows; ++r) {
    if (labels) text += quoted((*labels)[r]);
    for (std::size_t k = 0; k < columns.size(); ++k)
      text += (k || labels ? "," : "") + number_cell(columns[k][r]);
    text += '\n';
  }
  return text;
}

// The table's notes and provenance, beside it, so that the table itself is
// one header line and rows (pandas.read_csv reads it as is). No timestamp:
// a resumed run writes the same bytes as an uninterrupted one.
void write_sidecar(const std::filesystem::path& path, const std::vector<std::string>& names,
                   const std::vector<std::string>& units, std::size_t rows, const std::vector<std::string>& notes) {
  nlohmann::json unit_of = nlohmann::json::object();
  for (std::size_t k = 0; k < names.size(); ++k) unit_of[names[k]] = units[k];
  const nlohmann::json j = {{"file", path.filename().string()},
                            {"columns", names},
                            {"units", unit_of},
                            {"rows", rows},
                            {"notes", notes},
                            {"generator", "wearscale " + version()}};
  write_file_atomically(csv_sidecar(path), j.dump(2) + "\n");
}

}  // namespace

std::string csv_column_name(const std::string& name, const std::string& unit) {
  if (unit.empty()) throw std::invalid_argument("write_csv: column '" + name + "' has no unit (\"1\" if dimensionless)");
  if (unit == "1") return name;
  // "J/m^2" → numerator "J", denominator "m^2"; factors joined by a space or '·'.
  std::vector<std::string> words;
  const auto slash = unit.find('/');
  for (int part = 0; part < 2; ++part) {
    std::string text = part == 0 ? unit.substr(0, slash) : slash == std::string::npos ? "" : unit.substr(slash + 1);
    if (part == 1 && text.size() > 2 && text.front() == '(' && text.back() == ')')  // "mm^3/(N·m)"
      text = text.substr(1, text.size() - 2);
    for (std::size_t at; (at = text.find("·")) != std::string::npos;) text.replace(at, std::string("·").size(), " ");
    for (std::size_t start = 0; start < text.size();) {
      const auto space = text.find_first_of(" *", start);
      const std::string factor = text.substr(start, space == std::string::npos ? std::string::npos : space - start);
      if (!factor.empty() && factor != "1") words.push_back(factor_word(factor, part == 1));
      if (space == std::string::npos) break;
      start = space + 1;
    }
  }
  std::string out = name;
  for (const auto& w : words) out += "_" + w;
  for (const char c : out.substr(name.size()))
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_') || words.empty())
      throw std::invalid_argument("write_csv: cannot spell the unit '" + unit + "' of column '" + name + "'");
  return out;
}

std::filesystem::path csv_sidecar(const std::filesystem::path& csv) {
  auto out = csv;
  out += ".json";
  return out;
}

namespace {
// The header names and units of `names` in `units` (the label column first, without a unit).
std::pair<std::vector<std::string>, std::vector<std::string>> headers(const std::string* label_name,
                                                                      const std::vector<std::string>& names,
                                                                      const std::vector<std::string>& units) {
  if (units.size() != names.size()) throw std::invalid_argument("write_csv: names and units differ in count");
  std::vector<std::string> header, unit;
  if (label_name) header.push_back(*label_name), unit.push_back("");
  for (std::size_t k = 0; k < names.size(); ++k) header.push_back(csv_column_name(names[k], units[k]));
  unit.insert(unit.end(), units.begin(), units.end());
  return {header, unit};
}
}  // namespace

void write_csv(const std::filesystem::path& path, const std::vector<std::string>& names,
               const std::vector<std::span<const double>>& columns, const std::vector<std::string>& units,
               const std::vector<std::string>& notes) {
  const auto [header, unit] = headers(nullptr, names, units);
  write_file_atomically(path, table_text(nullptr, header, columns));
  write_sidecar(path, header, unit, row_count(nullptr, columns), notes);
}

void write_csv(const std::filesystem::path& path, const std::string& label_name, const std::vector<std::string>& labels,
               const std::vector<std::string>& names, const std::vector<std::span<const double>>& columns,
               const std::vector<std::string>& units, const std::vector<std::string>& notes) {
  const auto [header, unit] = headers(&label_name, names, units);
  write_file_atomically(path, table_text(&labels, header, columns));
  write_sidecar(path, header, unit, row_count(&labels, columns), notes);
}

}  // namespace wearscale
