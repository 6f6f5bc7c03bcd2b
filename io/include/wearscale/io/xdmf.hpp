#pragma once
// XDMF sidecars: a small XML file beside an HDF5 file that tells ParaView
// (and VisIt) how to read its 2D fields as a uniform grid in the XY plane.
//
// wearscale stores a field f(x_i, y_j) row-major with y fastest (i·ny + j,
// Grid2D), while VTK's image data runs x fastest. So that ParaView shows x
// along its X axis without copying any data, each field gets a view in the
// same HDF5 file — an HDF5 virtual dataset /xdmf/<dataset> of shape ny × nx
// mapping onto the stored rows — and the sidecar points at the views: a
// 3DCoRectMesh of 1 × ny × nx points, origin and spacing in double
// precision. Field snapshots of one run form a temporal collection, its time
// being a quantity such as the sliding distance.
#include <array>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "wearscale/core/grid.hpp"

namespace wearscale {

class H5Writer;

struct XdmfField {
  std::string dataset;  ///< path inside the HDF5 file of a 2D field (nx × ny), e.g. "/fields/pressure"
  std::string name;     ///< name shown in ParaView
};

/// The view ParaView reads for `dataset`: "/xdmf" + dataset.
std::string xdmf_view(const std::string& dataset);

/// A sidecar under construction: add() the fields (once written to the HDF5
/// file, before its commit), then write() the XML (after the commit).
class XdmfSidecar {
 public:
  /// Fields on `grid`; the first node sits at `origin` (x, y), the others
  /// grid.dx(), grid.dy() apart.
  explicit XdmfSidecar(const Grid2D& grid, std::array<double, 2> origin = {0.0, 0.0});

  /// The fields of the file (a single grid): writes their views into `h5`.
  XdmfSidecar& add(H5Writer& h5, const std::vector<XdmfField>& fields);
  /// The same for a file whose views another writer already added (the
  /// process that laid out a LaidOutFile, with add() on its own sidecar).
  XdmfSidecar& add_written(const std::vector<XdmfField>& fields);
  /// One snapshot of a temporal collection at `time` (e.g. the sliding
  /// distance); snapshots are shown in the order added.
  XdmfSidecar& add_step(H5Writer& h5, double time, const std::vector<XdmfField>& fields);

  std::size_t steps() const { return steps_.size(); }

  /// Writes the sidecar `xdmf_path` (atomically) for `h5_file`, which it
  /// names relative to the sidecar's folder. A collection of steps is
  /// temporal, with `time_name` in the steps' names (e.g. "s = 0.0012 m").
  void write(const std::filesystem::path& xdmf_path, const std::filesystem::path& h5_file,
             const std::string& time_name = "t", const std::string& time_unit = "") const;

 private:
  struct Step {
    std::optional<double> time;
    std::vector<XdmfField> fields;
  };
  void add_views(H5Writer& h5, const std::vector<XdmfField>& fields) const;
  Grid2D grid_;
  std::array<double, 2> origin_;
  std::vector<Step> steps_;
};

}  // namespace wearscale
