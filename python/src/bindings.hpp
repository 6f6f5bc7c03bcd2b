#pragma once
// One function per submodule of `wearscale._wearscale` (the compiled half of
// the package; python/wearscale/*.py is the other).
#include <pybind11/pybind11.h>

namespace wearscale::python {

void bind_surface(pybind11::module_& m);
void bind_contact(pybind11::module_& m);
void bind_materials(pybind11::module_& m);
void bind_wear(pybind11::module_& m);
void bind_dem(pybind11::module_& m);
void bind_io(pybind11::module_& m);
void bind_run(pybind11::module_& m);
/// MPI when the interpreter runs under mpirun/srun (mpi_session.cpp); `m` gets rank() and size().
void start_mpi(pybind11::module_& m);

}  // namespace wearscale::python
