#pragma once
// Reading measured or generated topographies, writing surfaces.
//
// Text grids: one row per x index i, one value per y index j, separated by
// commas, semicolons, spaces or tabs; lines starting with '#' are comments,
// and the comments "# lx = <length>" / "# ly = <length>" give the sizes
// (a number in metres, or a number with a unit: "# lx = 877 um"). A first
// non-comment line with no number at all is taken as a column header and
// skipped. HDF5: a 2D dataset, its sizes in attributes lx, ly (as written by
// write_surface or H5Writer::write_field).
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "wearscale/bem/surface_generator.hpp"
#include "wearscale/core/field.hpp"
#include "wearscale/core/hdf5_file.hpp"

namespace wearscale::bem {

inline constexpr const char* default_surface_dataset = "/surface/height";

/// Sizes given by the caller; each, when set, overrides what the file says.
struct TopographySize {
  std::optional<double> lx, ly;
};

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

/// By extension: .h5/.hdf5/.hdf → read_topography_h5, anything else → text.
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
