#include "arrays.hpp"

#include <cmath>
#include <cstring>

#include <fmt/format.h>

#include "wearscale/core/errors.hpp"

namespace wearscale::python {

void require_real_array(py::handle source) {
  const py::array a = py::isinstance<py::array>(source)
                          ? py::reinterpret_borrow<py::array>(source)
                          : py::array(py::module_::import("numpy").attr("asarray")(source));
  const char kind = a.dtype().kind();
  if (kind == 'f' || kind == 'i' || kind == 'u') return;
  const std::string dtype = py::str(a.dtype()).cast<std::string>();
  if (kind == 'c')
    throw InputError(fmt::format("an array of {} where real numbers are expected: its imaginary part would be lost; "
                                 "allowed: a real (float or integer) array (pass .real or abs() of it explicitly)",
                                 dtype));
  throw InputError(fmt::format("an array of {} where numbers are expected; allowed: a real (float or integer) array",
                               dtype));
}

py::array codes(const RealField& field) {
  py::array_t<std::uint8_t> out({field.rows(), field.cols()});
  auto* o = out.mutable_data();
  for (std::size_t k = 0; k < field.size(); ++k) o[k] = static_cast<std::uint8_t>(field[k]);
  return out;
}

Grid2D grid_of(const InArray& heights, double lx, double ly, const std::string& what) {
  if (heights.ndim() != 2)
    throw InputError(fmt::format("{}: a 2D array of heights is needed, got {} dimension(s)", what, heights.ndim()));
  const auto nx = static_cast<std::size_t>(heights.shape(0)), ny = static_cast<std::size_t>(heights.shape(1));
  if (nx < 2 || ny < 2) throw InputError(fmt::format("{}: the array is {} x {}; at least 2 x 2 points", what, nx, ny));
  if (!(lx > 0.0) || !std::isfinite(lx))
    throw InputError(fmt::format("{}: size lx = {} m; allowed: finite and > 0", what, lx));
  if (ly < 0.0) ly = lx * static_cast<double>(ny) / static_cast<double>(nx);
  if (!(ly > 0.0) || !std::isfinite(ly))
    throw InputError(fmt::format("{}: size ly = {} m; allowed: finite and > 0", what, ly));
  return Grid2D(nx, ny, lx, ly);
}

RealField field_from(const InArray& heights, const Grid2D& grid) {
  require_shape(heights, grid, "heights");
  RealField f(grid);
  std::memcpy(f.data(), heights.data(), sizeof(double) * grid.size());
  for (std::size_t k = 0; k < grid.size(); ++k)
    if (!std::isfinite(f[k]))
      throw InputError(fmt::format("heights: value at index ({}, {}) is {}; allowed: finite", k / grid.ny,
                                   k % grid.ny, f[k]));
  return f;
}

void require_shape(const InArray& a, const Grid2D& grid, const std::string& what) {
  if (a.ndim() != 2 || static_cast<std::size_t>(a.shape(0)) != grid.nx ||
      static_cast<std::size_t>(a.shape(1)) != grid.ny)
    throw InputError(fmt::format("{}: shape must be ({}, {}) as the grid's", what, grid.nx, grid.ny));
}

}  // namespace wearscale::python
