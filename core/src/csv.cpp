#include "wearscale/core/csv.hpp"

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
      text += fmt::format("{}{:.10g}", k || labels ? "," : "", columns[k][r]);
    text += '\n';
  }
  return text;
}

// The table's notes and provenance, beside it, so that the table itself is
// one header line and rows (pandas.read_csv reads it as is). No timestamp:
// a resumed run writes the same bytes as an uninterrupted one.
void write_sidecar(const std::filesystem::path& path, const std::vector<std::string>& names, std::size_t rows,
                   const std::vector<std::string>& notes) {
  const nlohmann::json j = {{"file", path.filename().string()},
                            {"columns", names},
                            {"rows", rows},
                            {"notes", notes},
                            {"generator", "wearscale " + version()}};
  write_file_atomically(csv_sidecar(path), j.dump(2) + "\n");
}

}  // namespace

std::filesystem::path csv_sidecar(const std::filesystem::path& csv) {
  auto out = csv;
  out += ".json";
  return out;
}

void write_csv(const std::filesystem::path& path, const std::vector<std::string>& names,
               const std::vector<std::span<const double>>& columns, const std::vector<std::string>& comments) {
  write_file_atomically(path, table_text(nullptr, names, columns));
  write_sidecar(path, names, row_count(nullptr, columns), comments);
}

void write_csv(const std::filesystem::path& path, const std::string& label_name, const std::vector<std::string>& labels,
               const std::vector<std::string>& names, const std::vector<std::span<const double>>& columns,
               const std::vector<std::string>& comments) {
  std::vector<std::string> header{label_name};
  header.insert(header.end(), names.begin(), names.end());
  write_file_atomically(path, table_text(&labels, header, columns));
  write_sidecar(path, header, row_count(&labels, columns), comments);
}

}  // namespace wearscale
