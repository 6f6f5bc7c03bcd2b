#pragma once
// A DEM time series: one row per sample (step, time, then named columns such
// as wall forces, stresses, energies, the number of worn particles), kept in
// memory and written to HDF5 with core's H5Writer as a table group
// (datasets step, time, <columns>, attribute "columns").
#include <filesystem>
#include <initializer_list>
#include <span>
#include <string>
#include <vector>

namespace wearscale {
class H5Writer;
}

namespace wearscale::dem {

class TimeSeries {
 public:
  /// Column names (besides step and time) and optionally their units.
  explicit TimeSeries(std::vector<std::string> columns, std::vector<std::string> units = {});

  /// Appends a row; `values` has one entry per column (invalid_argument
  /// otherwise).
  void append(long step, double time, std::span<const double> values);
  void append(long step, double time, std::initializer_list<double> values) {
    append(step, time, std::span<const double>(values.begin(), values.size()));
  }

  std::size_t rows() const { return step_.size(); }
  const std::vector<std::string>& columns() const { return names_; }
  const std::vector<double>& steps() const { return step_; }
  const std::vector<double>& times() const { return time_; }
  /// The values of a column by name (invalid_argument if unknown).
  const std::vector<double>& column(const std::string& name) const;

  /// Writes the table into an open file under `group` (e.g. "/dem/series").
  void write(H5Writer& out, const std::string& group) const;
  /// Writes a file of its own under `group` and commits it atomically: the
  /// file appears complete or not at all.
  void save(const std::filesystem::path& path, const std::string& group = "/series") const;

 private:
  std::vector<std::string> names_, units_;
  std::vector<double> step_, time_;
  std::vector<std::vector<double>> values_;
};

}  // namespace wearscale::dem
