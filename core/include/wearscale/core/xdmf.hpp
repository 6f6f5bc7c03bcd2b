#pragma once
// XDMF sidecars: a small XML file beside an HDF5 file that tells ParaView
// (and VisIt) how to read its 2D fields as a uniform grid.
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "wearscale/core/grid.hpp"

namespace wearscale {

struct XdmfField {
  std::string dataset;  ///< path inside the HDF5 file, e.g. "/fields/pressure"
  std::string name;     ///< name shown in ParaView
};

/// Writes `xdmf_path` (atomically) describing `fields`, all on `grid`, stored
/// in `h5_file` (referenced relative to the sidecar's folder). The first
/// node sits at `origin` (x, y), the others grid.dx(), grid.dy() apart.
void write_xdmf(const std::filesystem::path& xdmf_path, const std::filesystem::path& h5_file, const Grid2D& grid,
                const std::vector<XdmfField>& fields, std::array<double, 2> origin = {0.0, 0.0});

}  // namespace wearscale
