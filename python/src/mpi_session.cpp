// The interpreter under mpirun/srun (`mpirun -np 3 python3 script.py`): the
// module owns MPI as the CLI's main() does (mpi4py is not needed). Importing
// it in a process a launcher started initialises MPI (mpi::Session, threads
// funnelled: run() from the main thread) and MPI_Finalize runs at the
// interpreter's exit; then run() of a case with a [sweep] farms its runs over
// the ranks and rank 0 alone writes, as `mpirun -np N wearscale run` does.
// Started on its own, the interpreter stays serial and MPI is never touched.
#include <dlfcn.h>

#include <cstdlib>

#ifdef WEARSCALE_MPI
#include <mpi.h>
#endif

#include "bindings.hpp"
#include "wearscale/core/mpi.hpp"

namespace wearscale::python {

namespace {

mpi::Session* g_session = nullptr;

bool launched_by_mpi() {
  for (const char* v : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "PMI_RANK"})
    if (std::getenv(v) != nullptr) return true;
  return false;
}

// Python loads an extension module's libraries without RTLD_GLOBAL, but Open
// MPI's components (dlopen'ed by MPI_Init) resolve their symbols in libmpi:
// the library is made global first, as mpi4py does.
void make_mpi_global() {
#ifdef WEARSCALE_MPI
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&MPI_Init_thread), &info) != 0 && info.dli_fname != nullptr)
    (void)::dlopen(info.dli_fname, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD);
#endif
}

}  // namespace

void start_mpi(pybind11::module_& m) {
  if (g_session == nullptr && mpi::built_with_mpi() && launched_by_mpi()) {
    make_mpi_global();
    static int argc = 0;
    static char* no_args[] = {nullptr};
    static char** argv = no_args;
    g_session = new mpi::Session(argc, argv);
    // MPI_Finalize at the interpreter's exit (atexit runs before the module is torn down).
    pybind11::module_::import("atexit").attr("register")(pybind11::cpp_function([] {
      delete g_session;
      g_session = nullptr;
    }));
  }
  m.def("rank", [] { return mpi::rank(); },
        "This process's rank in the MPI job the interpreter runs in (0 when not under mpirun/srun).");
  m.def("size", [] { return mpi::size(); },
        "The number of ranks of that job (1 when not under mpirun/srun): run() of a [sweep] farms its runs over them.");
}

}  // namespace wearscale::python
