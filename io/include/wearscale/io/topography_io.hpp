#pragma once
// Reading measured or generated topographies, writing surfaces.
//
// Formats, recognised by their content (the extension only names what is
// missing): ISO 25178-72 X3P (.x3p), Gwyddion (.gwy) and Gwyddion Simple
// Field (.gsf), Digital Surf (.sur), ISO 25178-71 SDF (.sdf, ASCII and
// binary), Zygo (.datx, HDF5), wearscale's HDF5 (.h5), Gwyddion's ASCII
// matrix export and plain text grids. Each reader takes the physical size,
// the units and the missing-data mask from the file; docs/topography.md
// says how each format is read.
//
// Text grids: one row per x index i, one value per y index j, separated by
// commas, semicolons, spaces or tabs; lines starting with '#' are comments,
// and the comments "# lx = <length>" / "# ly = <length>" give the sizes
// (a number in metres, or a number with a unit: "# lx = 877 um"). A first
// non-comment line with no number at all is taken as a column header and
// skipped; "nan" marks a missing point. A Gwyddion ASCII export ("# Channel:",
// "# Width:", "# Height:", "# Value units:") has rows along y instead.
// HDF5: a 2D dataset, its sizes in attributes lx, ly (as written by
// write_surface or H5Writer::write_field).
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/field.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::bem {

inline constexpr const char* default_surface_dataset = "/surface/height";

/// Sizes given by the caller; each, when set, overrides what the file says.
struct TopographySize {
  std::optional<double> lx, ly;
};

/// What to do with the points a measurement marks as missing (NaN, masked,
/// non-measured): an explicit choice of the user, never a silent one.
enum class MissingPoints { Refuse, Fill };

/// The declaration of that choice: the option `surface analyze --missing`,
/// the case key contact.missing, their help and the error that stops a
/// file with missing points all come from here.
struct MissingPointsChoice {
  static constexpr const char* key = "missing";
  static constexpr const char* fallback = "refuse";
  static constexpr const char* allowed = "refuse | fill";
  static constexpr const char* doc =
      "Points the file marks as missing (NaN, masked, non-measured): refuse (default) stops and says how many "
      "and where; fill fills them by harmonic (Laplace) interpolation from the measured points around them";
};
/// "refuse" or "fill"; InputError naming `option` otherwise.
MissingPoints missing_points_from(std::string_view text, const std::string& option);
const char* name(MissingPoints m);

struct TopographyOptions {
  std::string dataset = default_surface_dataset;   ///< wearscale's HDF5: the heights' dataset
  TopographySize size;                              ///< overrides the file's sizes
  MissingPoints missing = MissingPoints::Refuse;
  /// Larger grids are refused before anything is allocated, so no header
  /// can make the reader take more memory than the file could fill.
  std::size_t max_points = std::size_t(1) << 28;
};

/// A topography and what the file said of it.
struct MeasuredTopography {
  RealField heights;       ///< metres, on the file's grid and size
  std::string format;      ///< e.g. "ISO 25178-72 X3P"
  std::size_t missing = 0; ///< points the file marks as missing (filled, if chosen)
};

/// Any supported format, recognised by its content. InputError naming the
/// file for a format wearscale does not read (with the list of those it
/// does), a malformed or truncated file, a missing size, non-finite
/// heights, and missing points unless `options.missing` fills them.
MeasuredTopography read_measured_topography(const std::filesystem::path& file, const TopographyOptions& options = {});
/// The same from a file's bytes (every format but the HDF5-based ones);
/// `name` stands for the file in messages and tells the format when the
/// content does not.
MeasuredTopography parse_measured_topography(std::string_view bytes, const std::string& name,
                                             const TopographyOptions& options = {});
/// "ISO 25178-72 X3P (.x3p), …": the formats wearscale reads, for messages and help.
std::string supported_topography_formats();

/// A height grid from a text/CSV file. InputError naming the file, line and
/// column for ragged rows, non-numbers, NaN or infinities, and for an empty
/// file or a missing size (neither a "# lx =" comment nor `size`). Either
/// reader refuses heights whose peak-to-valley span exceeds 1000 times the
/// longer side (heights and sizes in different units).
RealField read_topography_text(const std::filesystem::path& file, const TopographySize& size = {});
/// The same from the text itself; `name` stands for the file in messages.
RealField parse_topography_text(std::string_view text, const std::string& name, const TopographySize& size = {});

/// A height grid from an HDF5 dataset. InputError if the file or dataset is
/// missing, the dataset is not 2D, holds NaN/inf, or has no size (no lx/ly
/// attributes and none given).
RealField read_topography_h5(const std::filesystem::path& file, const std::string& dataset = default_surface_dataset,
                             const TopographySize& size = {});
/// The same from an open file. Attributes lx, ly must be one number each if
/// present; the grid is checked against the memory limit before it is read.
RealField read_topography_h5(const H5Reader& file, const std::string& dataset = default_surface_dataset,
                             const TopographySize& size = {});

/// Any format (read_measured_topography), missing points refused.
RealField read_topography(const std::filesystem::path& file, const std::string& dataset = default_surface_dataset,
                          const TopographySize& size = {});

/// Numeric attributes stored with a surface, e.g. its generation parameters.
using SurfaceAttributes = std::vector<std::pair<std::string, double>>;

/// Writes `h` to `file` as dataset /surface/height (unit "m", attributes lx, ly
/// and `attributes`), atomically, and an XDMF sidecar beside it (same name,
/// extension .xdmf) so ParaView opens it. Returns the sidecar's path.
std::filesystem::path write_surface(const std::filesystem::path& file, const RealField& h,
                                    const SurfaceAttributes& attributes = {});

/// The generation parameters hurst, k_l, k_r, k_s and seed, as attributes for write_surface.
SurfaceAttributes generation_attributes(const RoughSurfaceSpec& spec);

/// A numeric attribute of a dataset of an HDF5 file, if it has one (nullopt
/// also for text files).
std::optional<double> read_surface_attribute(const std::filesystem::path& file, const std::string& dataset,
                                             const std::string& name);

}  // namespace wearscale::bem
