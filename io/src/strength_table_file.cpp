#include "wearscale/io/strength_table_file.hpp"

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::materials {

namespace {

// The columns, `<name>_<unit>` as every wearscale table: written in Pa; read
// in any of these pressure units (tables written before the SI convention
// are in GPa).
const char* const kNames[3] = {"pressure", "sigma_max", "sigma_dyn"};
struct PressureUnit {
  const char* name;
  double pascals;
};
constexpr PressureUnit kUnits[] = {{"Pa", 1.0}, {"kPa", 1e3}, {"MPa", 1e6}, {"GPa", 1e9}};

std::string trim(std::string s) {
  const auto b = s.find_first_not_of(" \t\r");
  const auto e = s.find_last_not_of(" \t\r");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) out.push_back(trim(cell));
  return out;
}


bool is_hdf5(const std::filesystem::path& p) {
  const auto ext = p.extension().string();
  return ext == ".h5" || ext == ".hdf5";
}

// A strength table has rows of a few pressures: 16 MiB is far beyond any.
constexpr std::uintmax_t kMaxTableBytes = std::uintmax_t{16} << 20;

// The provenance a table written by write_strength_table keeps in its
// sidecar <file>.csv.json ("notes": ["key: value", ...]), after any in the
// table's own '#' comments (hand-written and shipped tables).
void read_sidecar_provenance(const std::filesystem::path& file, StrengthTable& t) {
  const auto sidecar = csv_sidecar(file);
  std::error_code ec;
  if (!std::filesystem::exists(sidecar, ec)) return;
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(read_text_file(sidecar, "strength table sidecar", kMaxTableBytes));
  } catch (const nlohmann::json::exception& e) {
    throw InputError(fmt::format("{}: not JSON ({}); allowed: the sidecar wearscale writes beside {}",
                                 sidecar.string(), e.what(), file.filename().string()));
  }
  if (!j.is_object() || !j.contains("notes") || !j["notes"].is_array()) return;
  for (const auto& note : j["notes"]) {
    if (!note.is_string()) continue;
    const std::string text = note.get<std::string>();
    const auto colon = text.find(':');
    if (colon != std::string::npos && colon > 0)
      t.provenance.emplace_back(trim(text.substr(0, colon)), trim(text.substr(colon + 1)));
  }
  if (t.material.empty()) t.material = t.info("material");
}

StrengthTable read_csv(const std::filesystem::path& file) {
  auto t = parse_strength_table_csv(read_text_file(file, "strength table", kMaxTableBytes), file.string());
  read_sidecar_provenance(file, t);
  return t;
}

}  // namespace

StrengthTable parse_strength_table_csv(std::string_view text, const std::string& origin) {
  const std::filesystem::path file = origin;
  std::istringstream in{std::string(strip_utf8_bom(text))};  // spreadsheets write a byte-order mark
  StrengthTable t;
  t.origin = origin;
  std::string line;
  int line_no = 0;
  int col[3] = {-1, -1, -1};
  double scale[3] = {1.0, 1.0, 1.0};
  std::vector<std::string> header;
  std::size_t columns = 0;
  bool header_seen = false;
  std::vector<int> row_lines;
  while (std::getline(in, line)) {
    ++line_no;
    const std::string s = trim(line);
    if (s.empty()) continue;
    if (s[0] == '#') {
      const std::string body = trim(s.substr(1));
      const auto colon = body.find(':');
      if (colon != std::string::npos && colon > 0)
        t.provenance.emplace_back(trim(body.substr(0, colon)), trim(body.substr(colon + 1)));
      continue;
    }
    const auto cells = split_csv(s);
    if (!header_seen) {
      header_seen = true;
      columns = cells.size();
      header = cells;
      for (std::size_t c = 0; c < cells.size(); ++c)
        for (int k = 0; k < 3; ++k)
          for (const auto& u : kUnits)
            if (cells[c] == fmt::format("{}_{}", kNames[k], u.name)) {
              if (col[k] >= 0)
                throw InputError(fmt::format("{}:{}: two '{}' columns ('{}' and '{}')", file.string(), line_no,
                                             kNames[k], cells[static_cast<std::size_t>(col[k])], cells[c]));
              col[k] = static_cast<int>(c);
              scale[k] = u.pascals;
            }
      for (int k = 0; k < 3; ++k)
        if (col[k] < 0)
          throw InputError(fmt::format("{}:{}: missing column '{}_Pa'; the header must name pressure_Pa, "
                                       "sigma_max_Pa, sigma_dyn_Pa (or the same in kPa, MPa, GPa)",
                                       file.string(), line_no, kNames[k]));
      continue;
    }
    if (cells.size() != columns)
      throw InputError(fmt::format("{}:{}: {} values, the header has {} columns", file.string(), line_no, cells.size(),
                                   columns));
    double v[3];
    for (int k = 0; k < 3; ++k) {
      const std::string& cell = cells[static_cast<std::size_t>(col[k])];
      std::size_t used = 0;
      try {
        v[k] = std::stod(cell, &used);
      } catch (const std::exception&) {
        used = 0;
      }
      if (used == 0 || used != cell.size())
        throw InputError(fmt::format("{}:{}: column {} = '{}' is not a number", file.string(), line_no,
                                     header[static_cast<std::size_t>(col[k])], cell));
    }
    t.pressure.push_back(v[0] * scale[0]);
    t.sigma_max.push_back(v[1] * scale[1]);
    t.sigma_dyn.push_back(v[2] * scale[2]);
    row_lines.push_back(line_no);
  }
  if (!header_seen) throw InputError(fmt::format("{}: empty strength table (no header line)", file.string()));
  t.material = t.info("material");
  validate(t, [&](std::size_t r) { return fmt::format("{}:{}", file.string(), row_lines[r]); });
  return t;
}

namespace {

// One column: a 1D dataset whose "unit" attribute is a pressure unit ("Pa"
// as wearscale writes, "GPa", "MPa"), converted to Pa.
std::vector<double> read_column(const H5Reader& r, const std::string& name) {
  const std::string dataset = "/strength/" + name;
  if (!r.exists(dataset)) throw InputError(fmt::format("{}: missing dataset {}", r.name(), dataset));
  if (const auto shape = r.shape(dataset); shape.size() != 1)
    throw InputError(fmt::format("{}: dataset {} has {} dimensions; allowed: one (a column)", r.name(), dataset,
                                 shape.size()));
  const auto unit = r.string_attribute_if(dataset, "unit");
  if (!unit)
    throw InputError(fmt::format("{}: dataset {} has no 'unit' attribute; allowed: a pressure unit (\"Pa\", \"GPa\")",
                                 r.name(), dataset));
  double scale = 0.0;
  try {
    const auto q = units::parse_quantity("1 " + *unit);
    if (q.dimension == units::pressure) scale = q.value;
  } catch (const std::invalid_argument&) {
  }
  if (!(scale > 0.0))
    throw InputError(fmt::format("{}: dataset {} has unit '{}'; allowed: a pressure unit (\"Pa\", \"GPa\")", r.name(),
                                 dataset, *unit));
  auto values = r.read_series(dataset);
  for (auto& v : values) v *= scale;
  return values;
}

}  // namespace

StrengthTable parse_strength_table_h5(const H5Reader& r) {
  StrengthTable t;
  t.origin = r.name();
  t.pressure = read_column(r, "pressure");
  t.sigma_max = read_column(r, "sigma_max");
  t.sigma_dyn = read_column(r, "sigma_dyn");
  const std::string keys = r.string_attribute_if("/strength", "provenance_keys").value_or("");
  std::stringstream ss(keys);
  std::string key;
  while (std::getline(ss, key, ','))
    if (!key.empty()) t.provenance.emplace_back(key, r.string_attribute("/strength", key));
  t.material = t.info("material");
  validate(t);
  return t;
}



StrengthTable read_strength_table(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) throw InputError(fmt::format("{}: no such strength table", file.string()));
  return is_hdf5(file) ? H5Reader::guarded(file, parse_strength_table_h5) : read_csv(file);
}

void write_strength_table(const std::filesystem::path& file, const StrengthTable& table) {
  validate(table);
  std::vector<std::pair<std::string, std::string>> provenance;
  if (table.info("material").empty() && !table.material.empty()) provenance.emplace_back("material", table.material);
  provenance.insert(provenance.end(), table.provenance.begin(), table.provenance.end());

  if (is_hdf5(file)) {
    H5Writer w(file);
    w.write_series("/strength/pressure", table.pressure, "Pa");
    w.write_series("/strength/sigma_max", table.sigma_max, "Pa");
    w.write_series("/strength/sigma_dyn", table.sigma_dyn, "Pa");
    std::string keys;
    for (const auto& [k, v] : provenance) {
      w.set_attribute("/strength", k, v);
      keys += (keys.empty() ? "" : ",") + k;
    }
    w.set_attribute("/strength", "provenance_keys", keys);
    w.commit();
    return;
  }
  // One header line (pressure_Pa, sigma_max_Pa, sigma_dyn_Pa) and rows in SI;
  // the provenance in the sidecar <file>.csv.json, as every wearscale table.
  std::vector<std::string> notes;
  for (const auto& [k, v] : provenance) notes.push_back(fmt::format("{}: {}", k, v));
  write_csv(file, {"pressure", "sigma_max", "sigma_dyn"}, {table.pressure, table.sigma_max, table.sigma_dyn},
            {"Pa", "Pa", "Pa"}, notes);
}

}  // namespace wearscale::materials
