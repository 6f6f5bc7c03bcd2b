#pragma once
// One function per submodule of `wearscale._wearscale` (the compiled half of
// the package; python/wearscale/*.py is the other).
#include <pybind11/pybind11.h>

#include <string>

namespace wearscale::python {

void bind_surface(pybind11::module_& m);
void bind_contact(pybind11::module_& m);
void bind_materials(pybind11::module_& m);
void bind_wear(pybind11::module_& m);
void bind_dem(pybind11::module_& m);
void bind_io(pybind11::module_& m);
void bind_run(pybind11::module_& m);
/// `_study_keys(study)`: a registered study's keys as its key tables declare them (bind_study_keys.cpp).
void bind_study_keys(pybind11::module_& m);
/// The default of `key` ("contact.boundary") as `study`'s key tables word it;
/// std::logic_error if it declares none.
std::string study_default(const std::string& study, const std::string& key);
/// MPI when the interpreter runs under mpirun/srun (mpi_session.cpp); `m` gets rank() and size().
void start_mpi(pybind11::module_& m);

}  // namespace wearscale::python
