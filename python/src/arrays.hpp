#pragma once
// NumPy arrays in and out of wearscale fields. A field is row-major with y
// fastest (core/grid.hpp), so an (nx, ny) C-contiguous float64 array has the
// same layout: results are returned as views on the solver's own storage (no
// copy; the array keeps its owner alive), inputs are read once into the
// solver's FFTW-aligned storage (the solvers keep their surface).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "wearscale/core/field.hpp"

namespace wearscale::python {

namespace py = pybind11;

/// A real array argument, read as C-contiguous float64. Its caster converts
/// integer and float arrays (and nested lists of them) and refuses every
/// other kind with InputError (a ValueError) instead of casting: a complex
/// array would lose its imaginary part silently, strings and objects would be
/// parsed or fail obscurely. Every array a binding takes is one.
class InArray : public py::array_t<double, py::array::c_style | py::array::forcecast> {
 public:
  using Base = py::array_t<double, py::array::c_style | py::array::forcecast>;
  InArray() = default;
  explicit InArray(Base a) : Base(std::move(a)) {}
};

/// InputError unless `source` (an array, or what NumPy makes an array of) holds real numbers (dtype kind
/// 'f', 'i' or 'u'); the message names the dtype.
void require_real_array(py::handle source);

/// A read-only (nx, ny) view on `field`, kept alive through `owner`.
inline py::array view(const RealField& field, py::handle owner) {
  py::array a(py::dtype::of<double>(), {field.rows(), field.cols()},
              {sizeof(double) * field.cols(), sizeof(double)}, field.data(), owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// An (nx, ny) array that owns `field` (moved, not copied).
inline py::array owned(RealField&& field) {
  auto* held = new RealField(std::move(field));
  py::capsule owner(held, [](void* p) { delete static_cast<RealField*>(p); });
  return py::array(py::dtype::of<double>(), {held->rows(), held->cols()},
                   {sizeof(double) * held->cols(), sizeof(double)}, held->data(), owner);
}

/// A 1D array that owns `values`.
inline py::array owned(std::vector<double>&& values) {
  auto* held = new std::vector<double>(std::move(values));
  py::capsule owner(held, [](void* p) { delete static_cast<std::vector<double>*>(p); });
  return py::array(py::dtype::of<double>(), {held->size()}, {sizeof(double)}, held->data(), owner);
}

/// An (nx, ny) uint8 copy of a field holding small integer codes (stick/slip, regions).
py::array codes(const RealField& field);

/// The grid of a height array of `lx` × `ly` metres (ly < 0: square cells, ly = lx·ny/nx).
Grid2D grid_of(const InArray& heights, double lx, double ly, const std::string& what);

/// The heights as a field on `grid` (one copy into aligned storage).
RealField field_from(const InArray& heights, const Grid2D& grid);

/// Same shape as `grid` or ValueError-mapped InputError naming `what`.
void require_shape(const InArray& a, const Grid2D& grid, const std::string& what);

}  // namespace wearscale::python

namespace pybind11::detail {
template <>
struct type_caster<wearscale::python::InArray> {
  PYBIND11_TYPE_CASTER(wearscale::python::InArray, const_name("numpy.ndarray[numpy.float64]"));
  bool load(handle src, bool convert) {
    if (!convert && !wearscale::python::InArray::Base::check_(src)) return false;
    wearscale::python::require_real_array(src);
    auto a = wearscale::python::InArray::Base::ensure(src);
    if (!a) {
      PyErr_Clear();
      return false;
    }
    value = wearscale::python::InArray(std::move(a));
    return true;
  }
  static handle cast(const wearscale::python::InArray& src, return_value_policy, handle) {
    return src.inc_ref();
  }
};
}  // namespace pybind11::detail
