#pragma once
// HDF5 output and input: 1D series, column tables, 2D fields and attributes
// for provenance.
//
// Writing: the file is built in memory (HDF5's core driver) and written to
// disk by wearscale itself when committed, every write checked; it exists
// under its final name only once complete (commit()). A writer destroyed
// before commit — by an exception, or a killed process — leaves no file under
// the final name; a full disk or a read-only folder is an OutputError naming
// the file, never a crash inside HDF5. Chunked (large) datasets carry a
// Fletcher-32 checksum, so damaged data read back is an error, not numbers.
// Fields larger than one process should hold (the ranks' slabs of a grid
// above the gather limit) are laid out instead in a file built on disk
// (H5Storage::Disk): contiguous, reserved, written in place by the processes
// that hold their rows, without a checksum; the same commit.
//
// Reading: every dataset and attribute is checked for its type and shape
// before it is read, and its size against the memory limit, so a file from
// another tool (h5py, MATLAB) or a damaged one gives an InputError naming
// the file, the object and what was expected. HDF5 1.10 itself crashes on
// some malformed files (found by fuzzing, tests/fuzz): every reader of a file
// a user gives therefore runs through H5Reader::guarded, which performs the
// read in a child process first and refuses the file as damaged if that
// child crashes or hangs; a few milliseconds per file.
#include <array>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "wearscale/core/atomic_file.hpp"
#include "wearscale/core/field.hpp"

namespace wearscale {

/// Where an H5Writer builds its file until commit().
enum class H5Storage {
  Memory,  ///< in memory (HDF5's core driver): HDF5 never writes to disk itself
  Disk,    ///< under the temporary name on disk: for fields reserved by this writer and written in place by others
};

class H5Writer {
 public:
  /// Starts writing `final_path` (a placeholder temporary file is created
  /// beside it at once, so an unwritable folder fails here, before any work).
  /// Every file carries the root attributes `wearscale_version`, `created`
  /// (UTC) and, when built from git, `git_revision`.
  /// `partial`: the temporary name to build it under (default
  /// partial_path(final_path); another process's, for a LaidOutFile).
  explicit H5Writer(std::filesystem::path final_path, Commit mode = Commit::WithItsSet,
                    H5Storage storage = H5Storage::Memory, std::filesystem::path partial = {});
  ~H5Writer();
  H5Writer(const H5Writer&) = delete;
  H5Writer& operator=(const H5Writer&) = delete;

  /// A 1D dataset, e.g. a time series; groups in `path` are created on demand.
  void write_series(const std::string& path, std::span<const double> values, std::string_view unit = {});
  /// Columns of equal length as datasets of one group, with a "columns" attribute.
  void write_table(const std::string& group, const std::vector<std::string>& names,
                   const std::vector<std::span<const double>>& columns,
                   const std::vector<std::string>& units = {});
  /// A 2D field f(x_i, y_j), nx × ny, row-major (the first index runs along x,
  /// as h5py reads f[i, j]), with its attributes: `unit`, `lx`, `ly` (its size),
  /// `x0`, `y0` (where node (0, 0) sits: x_i = x0 + i·lx/nx, y_j = y0 + j·ly/ny),
  /// `axes` = "x,y" (what each index runs along) and `description`.
  void write_field(const std::string& path, const RealField& field, std::string_view unit = {},
                   std::string_view description = {}, std::array<double, 2> origin = {0.0, 0.0});
  /// A scalar dataset (shape ()).
  void write_scalar(const std::string& path, double value, std::string_view unit = {});
  /// String attribute on a group or dataset ("/" is the file): a scalar of
  /// variable length, UTF-8 (h5py reads a str), of any length (its text is
  /// kept in the file's heap, not in the object's 64 KiB header).
  void set_attribute(const std::string& object, const std::string& name, std::string_view value);
  void set_attribute(const std::string& object, const std::string& name, double value);
  /// A 64-bit integer attribute (counts, steps: read back exactly).
  void set_integer_attribute(const std::string& object, const std::string& name, std::int64_t value);
  /// A read-only view `view` of the 2D dataset `source` (already written,
  /// rows × cols) with its axes swapped (cols × rows): an HDF5 virtual
  /// dataset of this file, one mapping per source row, no data copied.
  void write_transposed_view(const std::string& view, const std::string& source);

  /// A 2D field of `grid`'s size (nx × ny, with lx, ly and `unit`) whose values
  /// are not written here (H5Storage::Disk only): contiguous, its space
  /// allocated in the file, unfilled. Returns its byte offset: value (i, j)
  /// goes at offset + 8 (i·ny + j), a little-endian double, written in place
  /// (write_in_place on partial()) once finish_layout() has run.
  std::uint64_t reserve_field(const std::string& path, const Grid2D& grid, std::string_view unit = {},
                              std::string_view description = {}, std::array<double, 2> origin = {0.0, 0.0});
  /// Ends the HDF5 part of an H5Storage::Disk file: its whole size reserved on
  /// disk first (so neither HDF5's closing writes nor the values written in
  /// place later can meet a full disk), then closed. OutputError naming the
  /// file if the disk cannot hold it. Nothing more can be added; commit() next.
  void finish_layout();
  /// finish_layout(), then the temporary file is the caller's: this writer
  /// no longer removes it (a LaidOutFile commits or removes it).
  void hand_over();

  /// Writes the file and moves it to its final name (with its OutputSet, if
  /// one is open for the folder and the mode says so). Without it, nothing appears.
  void commit();
  const std::filesystem::path& final_path() const { return final_; }
  const std::filesystem::path& partial() const { return partial_; }

 private:
  long long group(const std::string& path);  // opened hid_t of the (created) parent group of `path`
  void ensure_group(const std::string& group_path);
  bool exists(const std::string& object) const;
  void close();
  std::filesystem::path final_, partial_;
  Commit mode_;
  H5Storage storage_;
  long long file_ = -1;  // hid_t
  bool committed_ = false;
};

namespace detail {
/// What `read` did in a child process within `timeout_seconds`.
struct Trial {
  std::string failure;      ///< why it did not run to its end ("the HDF5 library crashed reading it (signal 11, …)"); "" if it did
  std::string input_error;  ///< the message of the InputError it raised, if any
};
/// Called inside a child, an empty Trial.
Trial try_in_child(const std::function<void()>& read, double timeout_seconds);
/// InputError "<name>: damaged or not what it claims: …" unless `read` runs
/// to its end in a child (a timeout of 5 s plus 1 s per 20 MB of `bytes`);
/// the child's own InputError if it raised one (the read is then not
/// repeated in this process).
void refuse_if_damaged(const std::string& name, double bytes, const std::function<void()>& read);
}  // namespace detail

/// `read()`, a reader of the HDF5 file `file` through the C API (lock_hdf5),
/// guarded as H5Reader::guarded: tried in a child process first, the file
/// refused as damaged if HDF5 crashes or hangs there.
template <class Read>
auto guarded_hdf5_read(const std::filesystem::path& file, Read&& read) {
  std::error_code ec;
  const double bytes = static_cast<double>(std::filesystem::file_size(file, ec));
  detail::refuse_if_damaged(file.string(), ec ? 0.0 : bytes, [&] { (void)read(); });
  return read();
}

class H5Reader {
 public:
  /// Opens an HDF5 file; InputError if missing or not HDF5.
  explicit H5Reader(const std::filesystem::path& path);
  /// Opens an HDF5 file image held in memory (`name` stands for it in
  /// messages): tests and fuzzing.
  static H5Reader from_image(std::string_view bytes, const std::string& name);

  /// `read(reader)` on `file`, tried first in a child process: if HDF5
  /// crashes or hangs there, InputError ("damaged or not what it claims")
  /// instead of the crash; else the result of `read` in this process (the
  /// same read of the same bytes takes the same path). For every file a user
  /// gives (topographies, strength tables, checkpoints).
  template <class Read>
  static auto guarded(const std::filesystem::path& file, Read&& read) {
    return guarded_hdf5_read(file, [&] { return read(H5Reader(file)); });
  }
  /// The same on a file image in memory (fuzzing).
  template <class Read>
  static auto guarded_image(std::string_view bytes, const std::string& name, Read&& read) {
    detail::refuse_if_damaged(name, static_cast<double>(bytes.size()), [&] { read(from_image(bytes, name)); });
    return read(from_image(bytes, name));
  }
  ~H5Reader();
  H5Reader(const H5Reader&) = delete;
  H5Reader& operator=(const H5Reader&) = delete;
  H5Reader(H5Reader&& other) noexcept;

  bool exists(const std::string& path) const;
  /// The dimensions of a dataset (empty for a scalar); InputError if it is absent or not a dataset.
  std::vector<std::size_t> shape(const std::string& dataset) const;
  /// Every value of a numeric (integer or floating-point) dataset of any
  /// rank, converted to double, in row-major order.
  std::vector<double> read_series(const std::string& dataset) const;
  /// A scalar or 1D dataset of 64-bit floats, bit for bit: what wearscale
  /// saves to read back exactly (checkpoints). Any other type or rank is refused.
  std::vector<double> read_exact(const std::string& dataset) const;
  double read_scalar(const std::string& dataset) const;
  /// A 2D numeric dataset as a field; the grid size comes from the number
  /// attributes lx, ly (defaults 1 × 1 if absent, e.g. a topography written
  /// by another tool; InputError if present but not one number each).
  RealField read_field(const std::string& dataset) const;

  /// A string attribute: fixed or variable length (h5py's default), a scalar
  /// or an array of one. InputError naming it if absent or of another kind.
  std::string string_attribute(const std::string& object, const std::string& name) const;
  /// The same, or nullopt if the object has no such attribute.
  std::optional<std::string> string_attribute_if(const std::string& object, const std::string& name) const;
  /// One number (integer or floating-point, a scalar or an array of one).
  double number_attribute(const std::string& object, const std::string& name) const;
  /// The same, or nullopt if the object has no such attribute (present but
  /// malformed is still an InputError).
  std::optional<double> number_attribute_if(const std::string& object, const std::string& name) const;
  /// One integer (of an integer type only: a float, NaN included, is refused).
  std::int64_t integer_attribute(const std::string& object, const std::string& name) const;

  const std::string& name() const { return name_; }

 private:
  H5Reader() = default;
  long long open_attribute(const std::string& object, const std::string& name, bool required) const;
  std::string name_;
  long long file_ = -1;
};

/// Holds the lock of the (not thread-safe) HDF5 library, with its error
/// printing off, for code that calls the HDF5 C API directly.
[[nodiscard]] std::unique_lock<std::recursive_mutex> lock_hdf5();

}  // namespace wearscale
