#pragma once
// What every CSV table wearscale writes must satisfy (docs/running.md,
// Outputs): one header line then rows, no '#' comments (a plain
// pandas.read_csv reads it as is), numbers in every cell but the label column,
// and a sidecar <table>.csv.json naming each column's unit, with the unit in
// the column's name by one convention: `<name>_<unit>`, "^" dropped and "/" as
// "_per_" (p_N_Pa, q_rad_per_m, pin_wear_m3); a dimensionless column (unit
// "1") plain, and then not ending like a unit. Independent of core/csv.cpp's
// spelling code, so that a change there shows here.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace csv_check {

inline std::vector<std::string> split_row(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cell += '"', ++i;
      else if (c == '"') quoted = false;
      else cell += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      cells.push_back(cell), cell.clear();
    } else {
      cell += c;
    }
  }
  cells.push_back(cell);
  return cells;
}

// "rad/m" → "rad_per_m", "m^3" → "m3", "J/m^2" → "J_per_m2", "mm^3/(N·m)" → "mm3_per_N_per_m"
// (every factor after the '/' divides).
inline std::string unit_word(std::string unit) {
  std::string out;
  bool denominator = false;
  for (std::size_t i = 0; i < unit.size(); ++i) {
    const bool dot = unit.compare(i, 2, "·") == 0;
    if (unit[i] == '^' || unit[i] == '(' || unit[i] == ')') continue;
    if (unit[i] == '/') out += "_per_", denominator = true;
    else if (unit[i] == ' ' || unit[i] == '*' || dot) out += denominator ? "_per_" : "_", i += dot ? 1 : 0;
    else out += unit[i];
  }
  return out;
}

inline bool is_number(const std::string& cell) {
  if (cell == "nan" || cell == "inf" || cell == "-inf") return true;
  char* end = nullptr;
  std::strtod(cell.c_str(), &end);
  return !cell.empty() && end == cell.c_str() + cell.size();
}

/// Every way `csv` breaks the rules (empty when it keeps them).
inline std::vector<std::string> problems(const std::filesystem::path& csv) {
  std::vector<std::string> out;
  auto fail = [&](const std::string& what) { out.push_back(csv.string() + ": " + what); };
  std::ifstream in(csv);
  std::string header_line, line;
  if (!std::getline(in, header_line)) return {csv.string() + ": empty"};
  if (header_line.starts_with("#")) fail("starts with a '#' comment line");
  const auto header = split_row(header_line);
  static const std::regex name(R"([A-Za-z][A-Za-z0-9_.-]*)");  // "-": a material pair, mu0_SiO2-Si
  std::set<std::string> seen;
  for (const auto& h : header) {
    if (!std::regex_match(h, name)) fail("column name '" + h + "' is not a plain identifier");
    if (!seen.insert(h).second) fail("column '" + h + "' twice");
  }
  const auto sidecar = std::filesystem::path(csv.string() + ".json");
  nlohmann::json side;
  try {
    std::ifstream s(sidecar);
    side = nlohmann::json::parse(s);
  } catch (const std::exception& e) {
    fail("no readable sidecar " + sidecar.filename().string() + " (" + e.what() + ")");
    return out;
  }
  if (side.value("columns", nlohmann::json::array()) != nlohmann::json(header)) fail("the sidecar lists other columns");
  const auto units = side.value("units", nlohmann::json::object());
  std::vector<bool> label(header.size(), false);
  // A dimensionless name may not end like one of these units.
  static const std::regex unit_like(R"(.*_(m|m2|m3|m4|s|N|Pa|GPa|MPa|J|kg|K|rad_per_m|m_per_s|per_s|per_m)$)");
  for (std::size_t k = 0; k < header.size(); ++k) {
    const auto& h = header[k];
    if (!units.contains(h) || !units[h].is_string()) {
      fail("the sidecar gives no unit for '" + h + "'");
      continue;
    }
    const std::string unit = units[h];
    label[k] = unit.empty();
    if (unit.empty() && k != 0) fail("'" + h + "' has no unit and is not the first (label) column");
    if (unit == "1" && std::regex_match(h, unit_like)) fail("'" + h + "' is dimensionless but is named like a unit");
    if (!unit.empty() && unit != "1" && !h.ends_with("_" + unit_word(unit)))
      fail("'" + h + "' is in " + unit + " but does not end in _" + unit_word(unit));
  }
  std::size_t rows = 0;
  for (int line_no = 2; std::getline(in, line); ++line_no, ++rows) {
    const auto cells = split_row(line);
    if (cells.size() != header.size()) {
      fail("line " + std::to_string(line_no) + " has " + std::to_string(cells.size()) + " cells, the header " +
           std::to_string(header.size()));
      continue;
    }
    for (std::size_t k = 0; k < cells.size(); ++k)
      if (!label[k] && !is_number(cells[k]))
        fail("line " + std::to_string(line_no) + ", column " + header[k] + ": '" + cells[k] + "' is not a number");
  }
  if (side.value("rows", -1) != static_cast<int>(rows)) fail("the sidecar gives another row count");
  return out;
}

/// The problems of every .csv under `dir`, and how many tables were checked.
inline std::vector<std::string> problems_under(const std::filesystem::path& dir, std::size_t& tables) {
  std::vector<std::string> out;
  tables = 0;
  if (!std::filesystem::exists(dir)) return out;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".csv") {
      ++tables;
      for (auto& p : problems(e.path())) out.push_back(std::move(p));
    }
  return out;
}

}  // namespace csv_check
