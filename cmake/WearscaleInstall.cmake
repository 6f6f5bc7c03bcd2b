# `cmake --install build --prefix P`: every layer's static library and its
# include/ folder (whole, so a header moving between libraries needs no rule
# here), the exported targets wearscale::<layer> with wearscaleConfig.cmake
# and wearscaleConfigVersion.cmake, a pkg-config file, the shipped data
# (share/wearscale/data, found by the library relative to the installed
# program or module, or through WEARSCALE_DATA), the example cases and scripts
# (share/wearscale/cases, share/wearscale/examples) and the CLI. The Python
# package installs from python/CMakeLists.txt. docs/install.md says how to use them.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(WEARSCALE_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/wearscale CACHE STRING
    "Where wearscaleConfig.cmake goes, relative to the prefix")

# The interface targets the layers link (flags, FFTW, HDF5, MPI) go with them.
foreach(helper flags fftw hdf5 mpi)
  set_target_properties(wearscale_${helper} PROPERTIES EXPORT_NAME ${helper})
endforeach()
install(TARGETS wearscale_flags wearscale_fftw wearscale_hdf5 wearscale_mpi EXPORT wearscaleTargets)

get_property(wearscale_layers GLOBAL PROPERTY WEARSCALE_LAYERS)
set(wearscale_pc_libs)
foreach(layer IN LISTS wearscale_layers)
  get_property(dir GLOBAL PROPERTY WEARSCALE_LAYER_${layer}_DIR)
  install(TARGETS wearscale_${layer} EXPORT wearscaleTargets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY ${dir}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  # pkg-config wants dependents before their dependencies: the layers were added bottom up.
  list(PREPEND wearscale_pc_libs "-lwearscale_${layer}")
endforeach()
list(JOIN wearscale_pc_libs " " WEARSCALE_PC_LIBS)
# The prefix relative to the .pc file's folder, so the installed tree may move.
file(RELATIVE_PATH WEARSCALE_PC_UP /p/${CMAKE_INSTALL_LIBDIR}/pkgconfig /p)
# What the exported targets carry as INTERFACE properties, for a plain compiler
# command line: HDF5 and, in an MPI build, MPI and FFTW-MPI (core's static
# library calls MPI). No installed header reads the WEARSCALE_VERSION macro
# (wearscale::version() gives it), so the .pc needs no quoted string define. toml++, FFTW, GSL and libzip come
# through Requires (their own .pc files; Debian's toml++ is a shared library
# with its own defines). tests/install compiles and runs a program with them.
set(pc_cflags)
set(pc_libs ${HDF5_C_LIBRARIES})
if(WEARSCALE_MPI)
  set(mpi_definitions ${MPI_CXX_COMPILE_DEFINITIONS})
  list(FILTER mpi_definitions EXCLUDE REGEX "SKIP_MPICXX")  # given below, once
  list(TRANSFORM mpi_definitions PREPEND "-D")
  list(APPEND pc_cflags -DWEARSCALE_MPI=1 -DOMPI_SKIP_MPICXX=1 -DMPICH_SKIP_MPICXX=1 ${mpi_definitions}
       ${MPI_CXX_COMPILE_OPTIONS})
  set(pc_include_dirs ${FFTW3_MPI_INCLUDE_DIR} ${MPI_CXX_INCLUDE_DIRS})
  list(APPEND pc_libs ${FFTW3_MPI_LIBRARY} ${MPI_CXX_LIBRARIES} ${MPI_CXX_LINK_FLAGS})
endif()
list(APPEND pc_include_dirs ${HDF5_C_INCLUDE_DIRS})
list(REMOVE_DUPLICATES pc_include_dirs)
list(REMOVE_ITEM pc_include_dirs /usr/include)  # a system folder given with -I would change the search order
list(TRANSFORM pc_include_dirs PREPEND "-I")
list(APPEND pc_cflags ${pc_include_dirs})
list(JOIN pc_cflags " " WEARSCALE_PC_CFLAGS)
list(JOIN pc_libs " " WEARSCALE_PC_DEPENDENCY_LIBS)

install(EXPORT wearscaleTargets NAMESPACE wearscale:: FILE wearscaleTargets.cmake
        DESTINATION ${WEARSCALE_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/wearscaleConfig.cmake.in
  ${PROJECT_BINARY_DIR}/wearscaleConfig.cmake INSTALL_DESTINATION ${WEARSCALE_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/wearscaleConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/wearscaleConfig.cmake ${PROJECT_BINARY_DIR}/wearscaleConfigVersion.cmake
        DESTINATION ${WEARSCALE_INSTALL_CMAKEDIR})

configure_file(${PROJECT_SOURCE_DIR}/cmake/wearscale.pc.in ${PROJECT_BINARY_DIR}/wearscale.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/wearscale.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/materials/data/ DESTINATION ${CMAKE_INSTALL_DATADIR}/wearscale/data)
# The example cases and scripts: the help's and the man page's examples name cases/<case>.toml,
# which the CLI finds here when the working folder has none (share/wearscale/cases).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/cases/ DESTINATION ${CMAKE_INSTALL_DATADIR}/wearscale/cases)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/examples/ DESTINATION ${CMAKE_INSTALL_DATADIR}/wearscale/examples
        PATTERN "__pycache__" EXCLUDE)
install(TARGETS wearscale RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
