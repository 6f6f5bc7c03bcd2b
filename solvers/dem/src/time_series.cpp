#include "wearscale/dem/time_series.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "wearscale/core/hdf5_file.hpp"

namespace wearscale::dem {

TimeSeries::TimeSeries(std::vector<std::string> columns, std::vector<std::string> units)
    : names_(std::move(columns)), units_(std::move(units)), values_(names_.size()) {
  if (!units_.empty() && units_.size() != names_.size())
    throw std::invalid_argument(fmt::format("TimeSeries: {} units for {} columns", units_.size(), names_.size()));
  for (std::size_t c = 0; c < names_.size(); ++c) {
    const auto& n = names_[c];
    if (n.empty() || n == "step" || n == "time" || n.find_first_of("/,") != std::string::npos ||
        std::count(names_.begin(), names_.end(), n) > 1)
      throw std::invalid_argument(fmt::format(
          "TimeSeries: column name '{}' is empty, repeated, reserved (step, time) or has '/' or ','", n));
  }
}

void TimeSeries::append(long step, double time, std::span<const double> values) {
  if (values.size() != names_.size())
    throw std::invalid_argument(
        fmt::format("TimeSeries: a row of {} values for {} columns", values.size(), names_.size()));
  step_.push_back(static_cast<double>(step));
  time_.push_back(time);
  for (std::size_t c = 0; c < values.size(); ++c) values_[c].push_back(values[c]);
}

const std::vector<double>& TimeSeries::column(const std::string& name) const {
  const auto it = std::find(names_.begin(), names_.end(), name);
  if (it == names_.end()) throw std::invalid_argument(fmt::format("TimeSeries: no column '{}'", name));
  return values_[static_cast<std::size_t>(it - names_.begin())];
}

void TimeSeries::write(H5Writer& out, const std::string& group) const {
  std::vector<std::string> names{"step", "time"};
  names.insert(names.end(), names_.begin(), names_.end());
  std::vector<std::span<const double>> columns{step_, time_};
  for (const auto& v : values_) columns.emplace_back(v);
  std::vector<std::string> units;
  if (!units_.empty()) {
    units = {"", "s"};
    units.insert(units.end(), units_.begin(), units_.end());
  }
  out.write_table(group, names, columns, units);
}

void TimeSeries::save(const std::filesystem::path& path, const std::string& group) const {
  H5Writer out(path);
  write(out, group);
  out.commit();
}

}  // namespace wearscale::dem
