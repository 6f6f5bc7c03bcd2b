#pragma once
// A periodic, uniform 2D grid of nx × ny points covering Lx × Ly.
//
// Storage is row-major with y fastest: point (i, j) sits at i·ny + j, at
// position (i·Lx/nx, j·Ly/ny). The r2c spectrum has nx × (ny/2 + 1) modes.
#include <cmath>
#include <numbers>
#include <cstddef>
#include <string>

namespace wearscale {

struct Grid2D {
  std::size_t nx = 0, ny = 0;
  double lx = 1.0, ly = 1.0;

  Grid2D() = default;
  Grid2D(std::size_t nx_, std::size_t ny_, double lx_, double ly_) : nx(nx_), ny(ny_), lx(lx_), ly(ly_) {}
  /// Square grid, n × n points over L × L.
  static Grid2D square(std::size_t n, double l) { return {n, n, l, l}; }

  std::size_t size() const { return nx * ny; }
  /// The grid of `rows` consecutive rows of this one (same spacing): a slab of
  /// a grid distributed over ranks. slab(nx) is the grid itself.
  Grid2D slab(std::size_t rows) const {
    return rows == nx ? *this : Grid2D(rows, ny, dx() * static_cast<double>(rows), ly);
  }
  double dx() const { return lx / static_cast<double>(nx); }
  double dy() const { return ly / static_cast<double>(ny); }
  double area() const { return lx * ly; }
  double cell_area() const { return dx() * dy(); }
  double x(std::size_t i) const { return static_cast<double>(i) * dx(); }
  double y(std::size_t j) const { return static_cast<double>(j) * dy(); }

  std::size_t index(std::size_t i, std::size_t j) const { return i * ny + j; }
  /// Periodic image of an arbitrary (possibly negative) index along x / y.
  std::size_t wrap_x(long i) const { return wrap(i, nx); }
  std::size_t wrap_y(long j) const { return wrap(j, ny); }
  std::size_t periodic_index(long i, long j) const { return index(wrap_x(i), wrap_y(j)); }

  // --- Spectral (r2c) layout -------------------------------------------------
  std::size_t spectral_ny() const { return ny / 2 + 1; }
  std::size_t spectral_size() const { return nx * spectral_ny(); }
  /// Signed integer frequency k of spectral row i (k in (−nx/2, nx/2]).
  long frequency_x(std::size_t i) const {
    const long k = static_cast<long>(i);
    return k <= static_cast<long>(nx / 2) ? k : k - static_cast<long>(nx);
  }
  long frequency_y(std::size_t j) const { return static_cast<long>(j); }
  /// Angular wavenumber q = 2πk/L.
  double wavenumber_x(std::size_t i) const { return 2.0 * std::numbers::pi * static_cast<double>(frequency_x(i)) / lx; }
  double wavenumber_y(std::size_t j) const { return 2.0 * std::numbers::pi * static_cast<double>(frequency_y(j)) / ly; }

  bool operator==(const Grid2D& o) const = default;
  std::string to_string() const;

 private:
  static std::size_t wrap(long i, std::size_t n) {
    const long m = static_cast<long>(n);
    const long r = i % m;
    return static_cast<std::size_t>(r < 0 ? r + m : r);
  }
};

}  // namespace wearscale
