#pragma once
// The readers of measured topographies, one file each: what a file holds
// before the caller's choices (sizes, missing points) are applied.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/topography_io.hpp"

namespace wearscale::bem::formats {

/// Heights as read, in metres, in wearscale's order (point (i, j) at
/// i·ny + j, i along x); instruments mostly store rows along y with x
/// fastest, which each reader turns around.
struct RawTopography {
  std::string format;                  ///< e.g. "ISO 25178-72 X3P"
  std::size_t nx = 0, ny = 0;          ///< points along x and y
  std::vector<double> height;          ///< nx·ny heights [m]; anything at a missing point
  std::vector<std::uint8_t> missing;   ///< 1 where the file has no measured height; empty: none
  std::optional<double> lx, ly;        ///< sizes [m] the file gives
  std::string where;                   ///< the file, for messages
  /// Where the first missing point sits in the file's own terms (e.g. "line 3, column 2").
  std::string first_missing;

  /// Allocates nx × ny points after checking them against `max_points` and
  /// the memory limit (the raw heights, a copy, a mask: 25 B per point).
  void allocate(std::size_t nx_, std::size_t ny_, std::size_t max_points);
  double& at(std::size_t i, std::size_t j) { return height[i * ny + j]; }
  void mark_missing(std::size_t i, std::size_t j);
};

/// InputError "<where>: <problem>".
[[noreturn]] void refuse(const std::string& where, const std::string& problem);

// --- Little-endian (or big-endian) fields of binary headers ----------------
/// A bounds-checked reader over the bytes of a file.
class Bytes {
 public:
  Bytes(std::string_view data, std::string where, bool big_endian = false)
      : data_(data), where_(std::move(where)), big_(big_endian) {}
  std::size_t size() const { return data_.size(); }
  std::size_t pos() const { return pos_; }
  void seek(std::size_t p, const char* what);
  void skip(std::size_t n, const char* what) { seek(pos_ + n, what); }
  bool at_end() const { return pos_ >= data_.size(); }
  std::string_view take(std::size_t n, const char* what);
  std::uint8_t u8(const char* what);
  std::uint16_t u16(const char* what);
  std::int16_t i16(const char* what) { return static_cast<std::int16_t>(u16(what)); }
  std::uint32_t u32(const char* what);
  std::int32_t i32(const char* what) { return static_cast<std::int32_t>(u32(what)); }
  std::uint64_t u64(const char* what);
  std::int64_t i64(const char* what) { return static_cast<std::int64_t>(u64(what)); }
  double f32(const char* what);  ///< a float32, exactly as a double
  double f64(const char* what);
  /// A NUL-terminated string (the NUL consumed).
  std::string cstring(const char* what);
  const std::string& where() const { return where_; }
  void set_big_endian(bool big) { big_ = big; }

 private:
  std::string_view data_;
  std::string where_;
  std::size_t pos_ = 0;
  bool big_ = false;
};

/// A fixed-width text field of a binary header, trailing NULs and blanks cut.
std::string trimmed_field(std::string_view raw);

/// Metres per unit of a length unit as instruments write it ("m", "mm",
/// "um", "µm" in UTF-8, Latin-1 or MS-DOS code page, "nm", "Å", "pm", and
/// Zygo's "MicroMeters" …); nullopt for anything else.
std::optional<double> metres_per(std::string_view unit);

/// a·b, or nullopt if it overflows.
std::optional<std::size_t> product(std::size_t a, std::size_t b);

// --- The formats ----------------------------------------------------------
RawTopography parse_x3p(std::string_view bytes, const std::string& where, const TopographyOptions& o);
RawTopography parse_gwy(std::string_view bytes, const std::string& where, const TopographyOptions& o);
RawTopography parse_gsf(std::string_view bytes, const std::string& where, const TopographyOptions& o);
RawTopography parse_sur(std::string_view bytes, const std::string& where, const TopographyOptions& o);
RawTopography parse_sdf(std::string_view bytes, const std::string& where, const TopographyOptions& o);
/// A text grid: wearscale's own (rows along x, "# lx =" comments) or a
/// Gwyddion ASCII export (rows along y, "# Width:" header).
RawTopography parse_text(std::string_view text, const std::string& where, const TopographyOptions& o);
/// Zygo's HDF5 container (.datx), from a file.
RawTopography read_datx(const std::filesystem::path& file, const TopographyOptions& o);
/// wearscale's own HDF5 (a 2D dataset with lx, ly attributes), read
/// through H5Reader::guarded.
RawTopography read_h5(const std::filesystem::path& file, const TopographyOptions& o);
/// The same from an open file: lx, ly one number each if present.
RawTopography read_h5(const H5Reader& file, const TopographyOptions& o);

}  // namespace wearscale::bem::formats
