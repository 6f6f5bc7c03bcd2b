# Every dependency comes from a Debian 12 package. A missing one stops the
# configuration with the name of the package that provides it.
find_package(PkgConfig QUIET)

function(wearscale_missing what package)
  message(FATAL_ERROR
    "wearscale needs ${what}, which was not found.\n"
    "Install it with:  apt-get install -y ${package}\n"
    "(or run .ci/install-deps, which installs everything wearscale needs)")
endfunction()

macro(wearscale_require_pkgconfig)
  if(NOT PkgConfig_FOUND)
    wearscale_missing("pkg-config" "pkg-config")
  endif()
endmacro()

# --- Eigen3 (header-only linear algebra) -------------------------------------
find_package(Eigen3 3.3 QUIET NO_MODULE)
if(NOT TARGET Eigen3::Eigen)
  wearscale_missing("Eigen3" "libeigen3-dev")
endif()

# --- FFTW3, double precision, with its OpenMP-threaded library ----------------
wearscale_require_pkgconfig()
pkg_check_modules(FFTW3 QUIET IMPORTED_TARGET fftw3)
find_library(FFTW3_OMP_LIBRARY NAMES fftw3_omp)
if(NOT FFTW3_FOUND OR NOT FFTW3_OMP_LIBRARY)
  wearscale_missing("FFTW3 (double, with fftw3_omp)" "libfftw3-dev")
endif()
add_library(wearscale_fftw INTERFACE)
target_link_libraries(wearscale_fftw INTERFACE ${FFTW3_OMP_LIBRARY} PkgConfig::FFTW3)

# --- SUNDIALS (adaptive time integration: CVODE/ARKODE) -----------------------
find_package(SUNDIALS QUIET)
if(NOT SUNDIALS_FOUND)
  wearscale_missing("SUNDIALS" "libsundials-dev")
endif()

# --- GSL (roots, quadrature, fits, interpolation) ----------------------------
find_package(GSL QUIET)
if(NOT GSL_FOUND)
  wearscale_missing("GSL" "libgsl-dev")
endif()

# --- HDF5 (C API, serial) -----------------------------------------------------
set(HDF5_PREFER_PARALLEL OFF)
find_package(HDF5 QUIET COMPONENTS C)
if(NOT HDF5_FOUND)
  wearscale_missing("HDF5 (serial, C API)" "libhdf5-dev")
endif()
add_library(wearscale_hdf5 INTERFACE)
target_include_directories(wearscale_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS} ${HDF5_INCLUDE_DIRS})
target_link_libraries(wearscale_hdf5 INTERFACE ${HDF5_C_LIBRARIES})
target_compile_definitions(wearscale_hdf5 INTERFACE ${HDF5_C_DEFINITIONS} ${HDF5_DEFINITIONS})

# --- toml++ (case files) ------------------------------------------------------
find_package(tomlplusplus QUIET)
if(NOT TARGET tomlplusplus::tomlplusplus)
  wearscale_missing("toml++" "libtomlplusplus-dev")
endif()

# --- fmt, nlohmann-json, CLI11 ------------------------------------------------
find_package(fmt QUIET)
if(NOT TARGET fmt::fmt)
  wearscale_missing("fmt" "libfmt-dev")
endif()
find_package(nlohmann_json 3 QUIET)
if(NOT TARGET nlohmann_json::nlohmann_json)
  wearscale_missing("nlohmann-json" "nlohmann-json3-dev")
endif()
find_package(CLI11 QUIET)
if(NOT TARGET CLI11::CLI11)
  wearscale_missing("CLI11 (command-line parsing)" "libcli11-dev")
endif()

# --- OpenSSL (SHA-256: checkpoint checksums, keys of cached results; MD5 of X3P data)
find_package(OpenSSL QUIET COMPONENTS Crypto)
if(NOT TARGET OpenSSL::Crypto)
  wearscale_missing("OpenSSL (libcrypto)" "libssl-dev")
endif()

# --- libzip and pugixml (ISO 25178-72 X3P topographies: XML and data in a ZIP) --
# (pkg-config: Debian's libzip CMake package also wants the zipcmp tools installed)
pkg_check_modules(LIBZIP QUIET IMPORTED_TARGET libzip)
if(NOT LIBZIP_FOUND)
  wearscale_missing("libzip" "libzip-dev")
endif()
find_package(pugixml QUIET)
if(NOT TARGET pugixml::pugixml)
  wearscale_missing("pugixml" "libpugixml-dev")
endif()

# --- OpenMP -------------------------------------------------------------------
find_package(OpenMP QUIET COMPONENTS CXX)
if(NOT OpenMP_CXX_FOUND)
  wearscale_missing("OpenMP" "libgomp1 (comes with g++)")
endif()

# --- Test and benchmark frameworks -------------------------------------------
if(WEARSCALE_BUILD_TESTS)
  find_package(GTest QUIET)
  if(NOT TARGET GTest::gtest_main)
    wearscale_missing("GoogleTest" "libgtest-dev libgmock-dev")
  endif()
  # Boost's headers (property_tree): the tests read the XDMF files back with them.
  find_package(Boost 1.74 QUIET)
  if(NOT Boost_FOUND)
    wearscale_missing("Boost (headers, for the tests)" "libboost-dev")
  endif()
endif()
if(WEARSCALE_BUILD_BENCH)
  find_package(benchmark QUIET)
  if(NOT TARGET benchmark::benchmark)
    wearscale_missing("Google Benchmark" "libbenchmark-dev")
  endif()
endif()

# --- MPI (optional): Open MPI and FFTW's MPI transforms -----------------------
# WEARSCALE_MPI is ON when both are found; the serial build needs neither.
# MPI's C API as the C++ compiler sees it (MPI::MPI_CXX without the removed
# MPI-2 C++ bindings), so that a C++-only project can find_package(wearscale).
set(MPI_CXX_SKIP_MPICXX TRUE)
find_package(MPI QUIET COMPONENTS CXX)
find_library(FFTW3_MPI_LIBRARY NAMES fftw3_mpi)
find_path(FFTW3_MPI_INCLUDE_DIR NAMES fftw3-mpi.h)
set(wearscale_mpi_found OFF)
if(MPI_CXX_FOUND AND FFTW3_MPI_LIBRARY AND FFTW3_MPI_INCLUDE_DIR)
  set(wearscale_mpi_found ON)
endif()
option(WEARSCALE_MPI "Distributed runs under mpirun/srun (Open MPI, FFTW-MPI); ON when both are found"
       ${wearscale_mpi_found})
add_library(wearscale_mpi INTERFACE)
if(WEARSCALE_MPI)
  if(NOT MPI_CXX_FOUND)
    wearscale_missing("MPI (for WEARSCALE_MPI=ON)" "libopenmpi-dev openmpi-bin")
  endif()
  if(NOT FFTW3_MPI_LIBRARY OR NOT FFTW3_MPI_INCLUDE_DIR)
    wearscale_missing("FFTW-MPI (for WEARSCALE_MPI=ON)" "libfftw3-mpi-dev")
  endif()
  target_link_libraries(wearscale_mpi INTERFACE MPI::MPI_CXX ${FFTW3_MPI_LIBRARY})
  target_include_directories(wearscale_mpi SYSTEM INTERFACE ${FFTW3_MPI_INCLUDE_DIR})
  # The C API only: without these, mpi.h also pulls in the removed MPI-2 C++ bindings.
  target_compile_definitions(wearscale_mpi INTERFACE WEARSCALE_MPI=1 OMPI_SKIP_MPICXX=1 MPICH_SKIP_MPICXX=1)
  message(STATUS "wearscale: MPI on (${MPIEXEC_EXECUTABLE})")
else()
  message(STATUS "wearscale: MPI off (serial build)")
endif()
