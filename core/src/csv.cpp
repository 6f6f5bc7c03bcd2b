#include "wearscale/core/csv.hpp"

#include <stdexcept>

#include <fmt/format.h>

#include "wearscale/core/atomic_file.hpp"

namespace wearscale {

void write_csv(const std::filesystem::path& path, const std::vector<std::string>& names,
               const std::vector<std::span<const double>>& columns, const std::vector<std::string>& comments) {
  if (names.size() != columns.size()) throw std::invalid_argument("write_csv: names and columns differ in count");
  const std::size_t rows = columns.empty() ? 0 : columns[0].size();
  for (const auto& c : columns)
    if (c.size() != rows) throw std::invalid_argument("write_csv: columns differ in length");
  std::string text;
  for (const auto& c : comments) text += fmt::format("# {}\n", c);
  for (std::size_t k = 0; k < names.size(); ++k) text += (k ? "," : "") + names[k];
  text += '\n';
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t k = 0; k < columns.size(); ++k) text += fmt::format("{}{:.10g}", k ? "," : "", columns[k][r]);
    text += '\n';
  }
  write_file_atomically(path, text);
}

}  // namespace wearscale
