// Digital Surf (MountainsMap) .sur: a 512-byte header, a comment and a
// private zone, then xres × yres integers (16 or 32 bits), x fastest.
// Heights are raw·dz + z offset in the header's z unit, lateral steps in
// theirs; with the "non-measured points" flag set, values below zmin (the
// files write zmin − 2) mark points without a measurement. Format 0 is
// little-endian (PC), 257 big-endian (Macintosh).
#include <cmath>

#include <fmt/format.h>

#include "topography_formats.hpp"

namespace wearscale::bem::formats {

namespace {
double unit_of(std::string_view field, const std::string& where, const char* what) {
  const std::string unit = trimmed_field(field);
  const auto m = metres_per(unit);
  if (!m) refuse(where, fmt::format("the {} unit '{}' is not a unit of length", what, unit));
  return *m;
}
}  // namespace

RawTopography parse_sur(std::string_view bytes, const std::string& where, const TopographyOptions& o) {
  Bytes b(bytes, where);
  if (bytes.starts_with("DSCOMPRESSED"))
    refuse(where, "compressed Digital Surf data (DSCOMPRESSED) is not read; save it uncompressed");
  b.skip(12, "the signature");
  const std::uint16_t format = b.u16("the format");
  if (format != 0 && format != 257)
    refuse(where, fmt::format("format {} is neither PC (0) nor Macintosh (257)", format));
  if (format == 257) {
    b.set_big_endian(true);
    b.seek(12, "the format");
    b.u16("the format");
  }
  const std::uint16_t objects = b.u16("the number of objects");
  b.u16("the version");
  const std::uint16_t type = b.u16("the object type");
  if (type != 2)
    refuse(where, fmt::format("object type {} is not a surface (2); wearscale reads surfaces (profiles, series and "
                              "images are not topographies of a surface)", type));
  (void)objects;  // several objects: the first is read
  b.seek(86, "the header");
  const std::uint16_t special_points = b.u16("the non-measured points flag");
  b.seek(98, "the header");
  const std::uint16_t bits = b.u16("the point size");
  if (bits != 16 && bits != 32) refuse(where, fmt::format("points of {} bits; allowed: 16 or 32", bits));
  const std::int32_t zmin = b.i32("zmin");
  b.i32("zmax");
  const std::int32_t xres = b.i32("the points per line"), yres = b.i32("the number of lines");
  const std::uint32_t total = b.u32("the number of points");
  if (xres <= 0 || yres <= 0) refuse(where, fmt::format("a grid of {} × {} points", xres, yres));
  const auto n = product(static_cast<std::size_t>(xres), static_cast<std::size_t>(yres));
  if (!n || *n != total) refuse(where, fmt::format("{} points in all, but {} × {} on the grid", total, xres, yres));
  const double dx = b.f32("the x step"), dy = b.f32("the y step"), dz = b.f32("the z step");
  b.seek(180, "the header");
  const double ux = unit_of(b.take(16, "the x step unit"), where, "x step");
  const double uy = unit_of(b.take(16, "the y step unit"), where, "y step");
  const double uz = unit_of(b.take(16, "the z step unit"), where, "z step");
  b.seek(290, "the header");
  const std::uint16_t inversion = b.u16("the inversion");
  b.seek(334, "the header");
  const std::uint16_t comment = b.u16("the comment size"), privat = b.u16("the private zone size");
  b.seek(474, "the header");
  const double z_offset = b.f32("the z offset");
  for (const auto& [name, v] : {std::pair{"x step", dx}, std::pair{"y step", dy}})
    if (!(std::isfinite(v) && v > 0.0)) refuse(where, fmt::format("the {} is {}; allowed: > 0", name, v));
  if (!(std::isfinite(dz) && dz != 0.0)) refuse(where, fmt::format("the z step is {}; allowed: finite, not 0", dz));
  if (!std::isfinite(z_offset)) refuse(where, "the z offset is not finite");
  if (inversion > 3) refuse(where, fmt::format("inversion {} is not one of 0 (none), 1, 2, 3", inversion));

  const std::size_t data = 512 + std::size_t(comment) + privat;
  const auto need = product(*n, bits / 8);
  if (!need || data > bytes.size() || *need > bytes.size() - data)
    refuse(where, fmt::format("the file ends before its {} × {} points of {} bits", xres, yres, bits));
  RawTopography raw;
  raw.where = where;
  raw.format = "Digital Surf";
  raw.allocate(static_cast<std::size_t>(xres), static_cast<std::size_t>(yres), o.max_points);
  b.seek(data, "the comment and private zones");
  const std::size_t nx = raw.nx, ny = raw.ny;
  for (std::size_t r = 0; r < ny; ++r)
    for (std::size_t c = 0; c < nx; ++c) {
      const std::int64_t v = bits == 16 ? b.i16("the points") : b.i32("the points");
      // Inversion 1: z inverted; 2: also mirrored along x; 3: also along y.
      const std::size_t i = inversion == 2 ? nx - 1 - c : c, j = inversion == 3 ? ny - 1 - r : r;
      const double z = (static_cast<double>(v) * dz + z_offset) * uz;
      raw.at(i, j) = inversion > 0 ? -z : z;
      if (special_points == 1 && v < zmin) {
        if (raw.missing.empty()) raw.first_missing = fmt::format("point {} of line {} (non-measured)", c, r);
        raw.mark_missing(i, j);
      }
    }
  raw.lx = static_cast<double>(nx) * dx * ux;
  raw.ly = static_cast<double>(ny) * dy * uy;
  return raw;
}

}  // namespace wearscale::bem::formats
