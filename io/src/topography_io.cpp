// The entry points for topography files: recognising the format from the
// content, then applying the caller's choices (sizes, missing points) to
// what the format's reader found. Writing surfaces (HDF5 + XDMF).
#include "wearscale/io/topography_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iterator>
#include <sstream>
#include <system_error>

#include <fmt/format.h>

#include "topography_formats.hpp"
#include "wearscale/bem/harmonic_fill.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/memory_limit.hpp"
#include "wearscale/core/text_file.hpp"
#include "wearscale/io/hdf5_file.hpp"
#include "wearscale/io/xdmf.hpp"

namespace wearscale::bem {

namespace fs = std::filesystem;

namespace {

std::string lower_extension(const fs::path& file) {
  std::string ext = file.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

bool is_hdf5_name(const fs::path& file) {
  const auto ext = lower_extension(file);
  return ext == ".h5" || ext == ".hdf5" || ext == ".hdf";
}

constexpr std::string_view kHdf5Magic{"\x89HDF\r\n\x1a\n", 8};

// Formats of instruments that wearscale recognises by name but does not read.
const char* unsupported_format(const std::string& ext) {
  static const std::pair<const char*, const char*> known[] = {
      {".di", "Bruker/Veeco Nanoscope (.di)"}, {".spm", "Bruker/Veeco Nanoscope (.spm)"},
      {".plu", "Sensofar (.plu)"},             {".plux", "Sensofar (.plux)"},
      {".vk4", "Keyence (.vk4)"},              {".vk6", "Keyence (.vk6)"},
      {".vk", "Keyence (.vk)"},                {".zon", "Keyence (.zon)"},
      {".opd", "Wyko (.opd)"},                 {".opdx", "Bruker (.opdx)"},
      {".nms", "Nanovea (.nms)"},              {".lext", "Olympus LEXT (.lext)"},
      {".oir", "Olympus (.oir)"},              {".al3d", "Alicona (.al3d)"},
      {".ibw", "Igor binary wave (.ibw)"},     {".mi", "Agilent (.mi)"},
      {".bcr", "BCR-STM (.bcr)"},              {".nc", "NetCDF (.nc)"},
      {".mat", "MATLAB (.mat)"},               {".npy", "NumPy (.npy)"},
      {".tif", "TIFF (.tif)"},                 {".tiff", "TIFF (.tiff)"},
      {".frt", "FRT (.frt)"},                  {".mnt", "Mountains (.mnt)"},
      {".dat", "Zygo MetroPro (.dat)"},        {".xyz", "XYZ point cloud (.xyz)"}};
  for (const auto& [e, name] : known)
    if (ext == e) return name;
  return nullptr;
}

// A binary file: a NUL byte, or mostly control bytes, in its first 4 KiB.
bool looks_binary(std::string_view bytes) {
  const auto head = bytes.substr(0, 4096);
  std::size_t control = 0;
  for (const char c : head) {
    const auto u = static_cast<unsigned char>(c);
    if (u == 0) return true;
    if (u < 32 && u != '\n' && u != '\r' && u != '\t' && u != '\f') ++control;
  }
  return control * 8 > head.size();
}

[[noreturn]] void refuse_format(const std::string& where, const std::string& what) {
  throw InputError(fmt::format("{}: {}; wearscale reads {}", where, what, supported_topography_formats()));
}

/// Sizes from the caller first, then from the file; one missing side follows
/// from square pixels.
Grid2D resolve_grid(std::size_t nx, std::size_t ny, const TopographySize& given, std::optional<double> lx,
                    std::optional<double> ly, const std::string& where, const std::string& how) {
  if (given.lx) lx = given.lx;
  if (given.ly) ly = given.ly;
  if (!lx && !ly)
    throw InputError(fmt::format("{}: the size of the topography is not given; {}", where, how));
  const double rx = static_cast<double>(nx), ry = static_cast<double>(ny);
  if (!lx) lx = *ly * rx / ry;
  if (!ly) ly = *lx * ry / rx;
  for (const auto& [name, v] : {std::pair{"lx", *lx}, std::pair{"ly", *ly}})
    if (!(std::isfinite(v) && v > 0.0))
      throw InputError(fmt::format("{}: size {} = {:g} m is not allowed; allowed: > 0 m", where, name, v));
  return Grid2D(nx, ny, *lx, *ly);
}

// Heights spanning more than a thousand times the surface's side are not a
// surface (slopes beyond 10^3): most often heights in nm beside sizes in m.
// Heights this far apart would also overflow the analysis (h'_rms, areas).
void check_height_span(const RealField& h, const std::string& where) {
  double lo = h[0], hi = h[0];
  for (double v : h) lo = std::min(lo, v), hi = std::max(hi, v);
  const double side = std::max(h.grid().lx, h.grid().ly);
  if (!(hi - lo <= 1e3 * side))
    throw InputError(fmt::format("{}: heights from {:g} to {:g} m on a {:g} m × {:g} m surface (peak to valley {:g} "
                                 "times its side): are heights and sizes in the same unit? allowed: a peak-to-valley "
                                 "height of at most 1000 times the longer side",
                                 where, lo, hi, h.grid().lx, h.grid().ly, (hi - lo) / side));
}

// The caller's sizes and choice about missing points, applied to what the reader found.
MeasuredTopography finish(formats::RawTopography raw, const TopographyOptions& o) {
  const std::string how = raw.format == "text grid"
                              ? "add a '# lx = <length>' comment (and '# ly = ...') or pass the size"
                              : "the file records none, so pass the size";
  const Grid2D grid = resolve_grid(raw.nx, raw.ny, o.size, raw.lx, raw.ly, raw.where, how);
  MeasuredTopography out{RealField(grid), raw.format, 0};
  std::copy(raw.height.begin(), raw.height.end(), out.heights.begin());
  for (std::size_t i = 0; i < grid.nx; ++i)
    for (std::size_t j = 0; j < grid.ny; ++j) {
      const std::size_t k = grid.index(i, j);
      if (!raw.missing.empty() && raw.missing[k] != 0) {
        ++out.missing;
      } else if (!std::isfinite(out.heights[k])) {
        throw InputError(fmt::format("{}: the height at x index {}, y index {} is {}; allowed: finite heights (a "
                                     "missing point is marked as such, e.g. NaN)",
                                     raw.where, i, j, out.heights[k]));
      }
    }
  if (out.missing == 0) {
    check_height_span(out.heights, raw.where);
    return out;
  }
  const double share = 100.0 * static_cast<double>(out.missing) / static_cast<double>(grid.size());
  if (out.missing == grid.size())
    throw InputError(fmt::format("{}: every one of its {} points is missing (no measured height)", raw.where,
                                 grid.size()));
  if (o.missing == MissingPoints::Refuse)
    throw InputError(fmt::format(
        "{}: {} of {} points ({:.3g} %) have no measured height{}; choose what to do with them: {} = fill fills "
        "them by harmonic interpolation from the measured points around them (surface analyze --missing fill, "
        "case key contact.missing = \"fill\"); allowed: {}",
        raw.where, out.missing, grid.size(), share,
        raw.first_missing.empty() ? "" : fmt::format(" (the first at {})", raw.first_missing),
        MissingPointsChoice::key, MissingPointsChoice::allowed));
  harmonic_fill(out.heights, raw.missing);
  check_height_span(out.heights, raw.where);  // the filled points lie between measured ones
  log::info("{}: filled {} missing points ({:.3g} %) by harmonic interpolation", raw.where, out.missing, share);
  return out;
}

// A file's bytes: a regular file (not /dev/zero, a FIFO), of at most a sixth
// of the memory limit (the bytes, then a height per two bytes of text).
std::string slurp(const fs::path& file) {
  const double budget = memory_limit().bytes / 6.0;
  return read_text_file(file, "topography file", static_cast<std::uintmax_t>(std::min(budget, 1e18)));
}

}  // namespace

MissingPoints missing_points_from(std::string_view text, const std::string& option) {
  if (text == "refuse") return MissingPoints::Refuse;
  if (text == "fill") return MissingPoints::Fill;
  throw InputError(fmt::format("{} = '{}' is not a choice; allowed: {} ({})", option, text,
                               MissingPointsChoice::allowed, MissingPointsChoice::doc));
}

const char* name(MissingPoints m) { return m == MissingPoints::Fill ? "fill" : "refuse"; }

std::string supported_topography_formats() {
  return "ISO 25178-72 X3P (.x3p), Gwyddion (.gwy), Gwyddion Simple Field (.gsf), Digital Surf (.sur), "
         "ISO 25178-71 SDF (.sdf, ASCII and binary), Zygo (.datx), wearscale HDF5 (.h5), Gwyddion's ASCII export "
         "and text grids (.txt, .csv, .asc)";
}

MeasuredTopography parse_measured_topography(std::string_view bytes, const std::string& name,
                                             const TopographyOptions& o) {
  using namespace formats;
  const auto starts = [&](std::string_view magic) { return bytes.starts_with(magic); };
  if (starts("PK\x03\x04") || starts("PK\x05\x06")) return finish(parse_x3p(bytes, name, o), o);
  if (starts("GWYP")) return finish(parse_gwy(bytes, name, o), o);
  if (starts("GWYO")) refuse_format(name, "the old Gwyddion format (GWYO) is not read; resave it in Gwyddion");
  if (starts("Gwyddion Simple Field 1.0\n")) return finish(parse_gsf(bytes, name, o), o);
  if (starts("DIGITAL SURF")) return finish(parse_sur(bytes, name, o), o);
  if (starts("aISO-1.0") || starts("bISO-1.0")) return finish(parse_sdf(bytes, name, o), o);
  if (starts(kHdf5Magic)) refuse_format(name, "HDF5 content is read from a file, not from memory");
  const std::string ext = lower_extension(name);
  if (const char* known = unsupported_format(ext)) refuse_format(name, fmt::format("{} is not supported", known));
  if (looks_binary(bytes)) refuse_format(name, "not a topography format wearscale recognises (binary content)");
  return finish(parse_text(bytes, name, o), o);
}

MeasuredTopography read_measured_topography(const fs::path& file, const TopographyOptions& o) {
  const std::string name = file.string();
  std::error_code ec;
  const auto status = fs::status(file, ec);
  if (ec || !fs::exists(status)) throw InputError(fmt::format("{}: no such topography file", name));
  if (!fs::is_regular_file(status))
    throw InputError(fmt::format("{}: not a regular file (a device, FIFO, socket or folder); expected a topography file",
                                 name));
  char head[8] = {};
  std::ifstream(file, std::ios::binary).read(head, sizeof head);
  if (std::string_view(head, sizeof head) == kHdf5Magic) {
    // Zygo's files by name, or by their layout when renamed (and without the dataset asked for).
    bool datx = lower_extension(file) == ".datx";
    if (!datx)
      datx = H5Reader::guarded(file, [&](const H5Reader& reader) {
        return !reader.exists(o.dataset) && (reader.exists("/MetaData") || reader.exists("/Measurement/Surface"));
      });
    return finish(datx ? formats::read_datx(file, o) : formats::read_h5(file, o), o);
  }
  if (is_hdf5_name(file)) throw InputError(fmt::format("{}: not an HDF5 file", name));
  return parse_measured_topography(slurp(file), name, o);
}

RealField read_topography_text(const fs::path& file, const TopographySize& size) {
  TopographyOptions o;
  o.size = size;
  return finish(formats::parse_text(slurp(file), file.string(), o), o).heights;
}

RealField parse_topography_text(std::string_view content, const std::string& name, const TopographySize& size) {
  TopographyOptions o;
  o.size = size;
  return finish(formats::parse_text(content, name, o), o).heights;
}

RealField read_topography_h5(const fs::path& file, const std::string& dataset, const TopographySize& size) {
  TopographyOptions o;
  o.dataset = dataset;
  o.size = size;
  return finish(formats::read_h5(file, o), o).heights;
}

RealField read_topography_h5(const H5Reader& file, const std::string& dataset, const TopographySize& size) {
  TopographyOptions o;
  o.dataset = dataset;
  o.size = size;
  return finish(formats::read_h5(file, o), o).heights;
}

RealField read_topography(const fs::path& file, const std::string& dataset, const TopographySize& size) {
  TopographyOptions o;
  o.dataset = dataset;
  o.size = size;
  return read_measured_topography(file, o).heights;
}

namespace formats {

RawTopography read_h5(const fs::path& file, const TopographyOptions& o) {
  return H5Reader::guarded(file, [&](const H5Reader& reader) { return read_h5(reader, o); });
}

RawTopography read_h5(const H5Reader& reader, const TopographyOptions& o) {
  const std::string& dataset = o.dataset;
  if (!reader.exists(dataset))
    throw InputError(fmt::format("{}: no dataset '{}'; name the height dataset (e.g. --dataset /surface/height)",
                                 reader.name(), dataset));
  RawTopography raw;
  raw.where = fmt::format("{}: dataset '{}'", reader.name(), dataset);
  raw.format = "HDF5";
  // Sizes in attributes: one number each, or none (a malformed one is an error, not ignored).
  raw.lx = reader.number_attribute_if(dataset, "lx"), raw.ly = reader.number_attribute_if(dataset, "ly");
  const auto shape = reader.shape(dataset);
  if (shape.size() != 2) refuse(raw.where, fmt::format("not a 2D field (rank {})", shape.size()));
  raw.allocate(shape[0], shape[1], o.max_points);  // checked against the memory limit before reading
  const std::vector<double> values = reader.read_series(dataset);
  for (std::size_t k = 0; k < values.size(); ++k) {
    raw.height[k] = values[k];
    if (std::isnan(values[k])) {
      if (raw.missing.empty()) raw.first_missing = fmt::format("row {}, column {}", k / raw.ny + 1, k % raw.ny + 1);
      raw.mark_missing(k / raw.ny, k % raw.ny);
    }
  }
  return raw;
}

}  // namespace formats

fs::path write_surface(const fs::path& file, const RealField& h, const SurfaceAttributes& attributes) {
  XdmfSidecar xdmf(h.grid());
  fs::path sidecar = file;
  sidecar.replace_extension(".xdmf");
  {
    H5Writer writer(file);
    writer.write_field(default_surface_dataset, h, "m", "surface heights h(x, y)");
    for (const auto& [key, value] : attributes) writer.set_attribute(default_surface_dataset, key, value);
    writer.set_attribute("/surface", "description", "surface heights h(x_i, y_j), rows i along x, columns j along y");
    xdmf.add(writer, {{default_surface_dataset, "height"}});
    // The pair goes in sidecar last: an old sidecar never describes a new file.
    std::error_code ec;
    fs::remove(sidecar, ec);
    writer.commit();
  }
  xdmf.write(sidecar, file);
  return sidecar;
}

SurfaceAttributes generation_attributes(const RoughSurfaceSpec& spec) {
  return {{"hurst", spec.hurst}, {"k_l", spec.k_l}, {"k_r", spec.k_r}, {"k_s", spec.k_s},
          {"seed", static_cast<double>(spec.seed)}};
}

std::optional<double> read_surface_attribute(const fs::path& file, const std::string& dataset, const std::string& name) {
  if (!is_hdf5_name(file)) return std::nullopt;
  return H5Reader::guarded(file, [&](const H5Reader& reader) -> std::optional<double> {
    if (!reader.exists(dataset)) return std::nullopt;
    return reader.number_attribute_if(dataset, name);
  });
}

}  // namespace wearscale::bem
