// wearscale.io: datasets of wearscale's HDF5 outputs (run.h5, contact.h5, …)
// as NumPy arrays, so no h5py is needed to read a run's fields.
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "arrays.hpp"
#include "bindings.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/units.hpp"
#include "wearscale/io/csv.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale::python {

void bind_io(py::module_& m) {
  m.def("read", [](const std::filesystem::path& file, const std::string& dataset) {
          std::vector<double> values;
          std::vector<std::size_t> shape;
          {
            py::gil_scoped_release release;
            H5Reader h5(file);
            shape = h5.shape(dataset);
            values = h5.read_series(dataset);
          }
          py::array a = owned(std::move(values));
          std::vector<py::ssize_t> dims(shape.begin(), shape.end());
          return a.reshape(dims);
        }, py::arg("file"), py::arg("dataset"),
        "A numeric dataset of an HDF5 file, any rank, as a float64 array of its shape (scalars: shape ()). "
        "ValueError naming the file and dataset if either is missing.");
  m.def("exists", [](const std::filesystem::path& file, const std::string& path) { return H5Reader(file).exists(path); },
        py::arg("file"), py::arg("path"), "Whether the HDF5 file holds a group or dataset at `path`.");
  m.def("attribute", [](const std::filesystem::path& file, const std::string& object, const std::string& name) -> py::object {
          H5Reader h5(file);
          try {
            return py::float_(h5.number_attribute(object, name));
          } catch (const InputError&) {
            return py::str(h5.string_attribute(object, name));  // a string attribute, or the error naming it
          }
        }, py::arg("file"), py::arg("object"), py::arg("name"), "A string or number attribute (e.g. 'unit', 'lx').");
  m.def("column_name", [](const std::string& name, const std::string& unit) {
          try {
            return csv_column_name(name, unit);
          } catch (const std::invalid_argument& e) {
            throw InputError(std::string("io.column_name: ") + e.what());
          }
        }, py::arg("name"), py::arg("unit"),
        "The name of a quantity with its SI unit, as every CSV table of wearscale spells its columns and as the "
        "results of run() and of the contact solves are keyed: ('p_N', 'Pa') -> 'p_N_Pa', ('wear', 'm^3') -> "
        "'wear_m3', ('friction', '1') -> 'friction'.");
  m.def("quantity", [](const std::string& text) {
          try {
            const auto q = units::parse_quantity(text);
            return py::make_tuple(q.value, q.dimension.to_string());
          } catch (const std::invalid_argument& e) {
            throw InputError("io.quantity: '" + text + "': " + e.what());
          }
        }, py::arg("text"),
        "A case file's quantity (\"1 um\", \"8 mm/s\", \"2.5\") in SI: (value, SI unit of its dimension; '1' for a "
        "plain number).");
}

}  // namespace wearscale::python
