#pragma once
// HDF5 output and input: 1D series, column tables, 2D fields and string
// attributes for provenance. Output files exist under their final name only
// once complete (commit()); a writer destroyed before commit — by an
// exception, or a killed process — leaves no file under the final name.
#include <filesystem>
#include <mutex>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "wearscale/core/field.hpp"

namespace wearscale {

class H5Writer {
 public:
  /// Starts writing `final_path` under a temporary name beside it.
  explicit H5Writer(std::filesystem::path final_path);
  ~H5Writer();
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;

  /// A 1D dataset, e.g. a time series; groups in `path` are created on demand.
  void write_series(const std::string& path, std::span<const double> values, std::string_view unit = {});
  /// Columns of equal length as datasets of one group, with a "columns" attribute.
  void write_table(const std::string& group, const std::vector<std::string>& names,
                   const std::vector<std::span<const double>>& columns,
                   const std::vector<std::string>& units = {});
  /// A 2D field (nx × ny, row-major) with its grid size as attributes lx, ly.
  void write_field(const std::string& path, const RealField& field, std::string_view unit = {});
  void write_scalar(const std::string& path, double value, std::string_view unit = {});
  /// String attribute on a group or dataset ("/" is the file).
  void set_attribute(const std::string& object, const std::string& name, std::string_view value);
  void set_attribute(const std::string& object, const std::string& name, double value);
  /// A read-only view `view` of the 2D dataset `source` (already written,
  /// rows × cols) with its axes swapped (cols × rows): an HDF5 virtual
  /// dataset of this file, one mapping per source row, no data copied.
  void write_transposed_view(const std::string& view, const std::string& source);

  /// Closes the file and moves it to its final name. Without it, nothing appears.
  void commit();
  const std::filesystem::path& final_path() const { return final_; }
  const std::filesystem::path& partial() const { return partial_; }

 private:
  long long group(const std::string& path);  // opened hid_t of the (created) parent group of `path`
  void ensure_group(const std::string& group_path);
  bool exists(const std::string& object) const;
  void close();
  std::filesystem::path final_, partial_;
  long long file_ = -1;  // hid_t
  bool committed_ = false;
};

class H5Reader {
 public:
  /// Opens an HDF5 file; InputError if missing or not HDF5.
  explicit H5Reader(const std::filesystem::path& path);
  ~H5Reader();
  H5Reader(const H5Reader&) = delete;
  H5Reader& operator=(const H5Reader&) = delete;

  bool exists(const std::string& path) const;
  std::vector<std::size_t> shape(const std::string& dataset) const;
  std::vector<double> read_series(const std::string& dataset) const;
  double read_scalar(const std::string& dataset) const;
  /// A 2D dataset as a field; the grid size comes from attributes lx, ly
  /// (defaults 1 × 1 if absent, e.g. a topography written by another tool).
  RealField read_field(const std::string& dataset) const;
  std::string string_attribute(const std::string& object, const std::string& name) const;
  double number_attribute(const std::string& object, const std::string& name) const;

 private:
  std::filesystem::path path_;
  long long file_ = -1;
};

/// Holds the lock of the (not thread-safe) HDF5 library, with its error
/// printing off, for code that calls the HDF5 C API directly.
[[nodiscard]] std::unique_lock<std::recursive_mutex> lock_hdf5();

}  // namespace wearscale
