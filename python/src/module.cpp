// wearscale._wearscale: the submodules and the C++ → Python exceptions.
//   InputError     → wearscale.InputError(ValueError)         bad input: key, value, allowed range
//   OutputError    → wearscale.OutputError(InputError, OSError) an output that cannot be written
//   NumericalError → wearscale.NumericalError(ArithmeticError)  no convergence, NaN, breakdown
//   Interrupted    → KeyboardInterrupt
// The message is the C++ one, whole.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "wearscale/core/errors.hpp"
#include "wearscale/core/thread_waiting.hpp"
#include "wearscale/core/version.hpp"

namespace py = pybind11;

PYBIND11_MODULE(_wearscale, m) {
  m.doc() = "wearscale's compiled core; use the package `wearscale` (docs/python.md).";
  static py::exception<wearscale::InputError> input_error(m, "InputError", PyExc_ValueError);
  input_error.doc() = "Bad input (a ValueError): the message names the key or argument, its value and the allowed range.";
  py::object bases = py::make_tuple(input_error, py::handle(PyExc_OSError));
  static py::object output_error =
      py::reinterpret_steal<py::object>(PyErr_NewException("wearscale._wearscale.OutputError", bases.ptr(), nullptr));
  m.attr("OutputError") = output_error;
  static py::exception<wearscale::NumericalError> numerical_error(m, "NumericalError", PyExc_ArithmeticError);
  numerical_error.doc() = "A numerical failure (an ArithmeticError): the message names the solver, step and quantity.";
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const wearscale::OutputError& e) {
      PyErr_SetString(output_error.ptr(), e.what());
    } catch (const wearscale::InputError& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const wearscale::NumericalError& e) {
      PyErr_SetString(numerical_error.ptr(), e.what());
    } catch (const wearscale::Interrupted& e) {
      PyErr_SetString(PyExc_KeyboardInterrupt, e.what());
    }
  });
  m.attr("__version__") = WEARSCALE_VERSION;
  // What the package's __init__.py sets GOMP_SPINCOUNT to (the CLI's value).
  m.attr("_waiting_spin_count") = wearscale::waiting_spin_count;
  wearscale::python::bind_study_keys(m);

  auto surface = m.def_submodule("surface", "Rough surfaces: generation, roughness measures, PSD, topography files.");
  wearscale::python::bind_surface(surface);
  auto contact = m.def_submodule("contact", "BEM contact of a rigid surface on an elastic half-space.");
  wearscale::python::bind_contact(contact);
  auto materials = m.def_submodule("materials", "Material records, strength tables and the junction model.");
  wearscale::python::bind_materials(materials);
  auto wear = m.def_submodule("wear", "Adhesive wear maps (thesis ch. 3-5).");
  wearscale::python::bind_wear(wear);
  auto dem = m.def_submodule("dem", "The coarse-grained cohesive DEM (thesis ch. 6-7).");
  wearscale::python::bind_dem(dem);
  auto io = m.def_submodule("io", "HDF5 datasets of wearscale's outputs as NumPy arrays.");
  wearscale::python::bind_io(io);
  auto runner = m.def_submodule("runner", "Cases through the CLI's runner.");
  wearscale::python::bind_run(runner);
  auto mpi = m.def_submodule("mpi", "The MPI job the interpreter runs in under mpirun/srun (the C++ side owns MPI).");
  wearscale::python::start_mpi(mpi);
}
