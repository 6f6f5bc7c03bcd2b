# ctest install.*: `cmake --install` of the build tree into a scratch prefix,
# then (STEP=cxx) an external CMake project that find_package(wearscale)s it,
# links wearscale::bem and checks a Hertz contact, or (STEP=python) the
# installed Python package imported from outside the source and build trees.
#   cmake -DBUILD=<build tree> -DPREFIX=<scratch> -DSTEP=cxx|python [-DPYTHON=...] [-DPYDIR=...] -P install_test.cmake
function(run)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}")
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${err}")
  endif()
endfunction()

file(REMOVE_RECURSE ${PREFIX})
run(${CMAKE_COMMAND} --install ${BUILD} --prefix ${PREFIX})
# The installed tree may not point back at the source or build trees.
file(GLOB_RECURSE configs ${PREFIX}/*.cmake ${PREFIX}/*.pc)
foreach(f IN LISTS configs)
  file(READ ${f} text)
  string(FIND "${text}" "${SOURCE}" at)
  if(NOT at EQUAL -1)
    message(FATAL_ERROR "${f} names the source tree ${SOURCE}")
  endif()
endforeach()

if(STEP STREQUAL "cxx")
  set(consumer ${PREFIX}-consumer)
  file(REMOVE_RECURSE ${consumer})
  run(${CMAKE_COMMAND} -S ${SOURCE}/tests/install/consumer -B ${consumer} -DCMAKE_BUILD_TYPE=Release
      -DCMAKE_PREFIX_PATH=${PREFIX} -DCMAKE_CXX_COMPILER=${CXX})
  run(${CMAKE_COMMAND} --build ${consumer})
  # WEARSCALE_DATA unset: the program finds share/wearscale/data above its own
  # folder only if it sits in the prefix; it is run from the consumer's build
  # tree, so it is pointed at the installed data explicitly, as a user would.
  run(${CMAKE_COMMAND} -E env WEARSCALE_DATA=${PREFIX}/share/wearscale/data ${consumer}/hertz_consumer)
  # pkg-config names the libraries and headers of the same prefix.
  run(${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${PREFIX}/lib/pkgconfig pkg-config --cflags --libs wearscale)
  # The installed CLI finds its data relative to itself.
  run(${CMAKE_COMMAND} -E env --unset=WEARSCALE_DATA --unset=WEARSCALE_DATA_DIR ${PREFIX}/bin/wearscale version)
elseif(STEP STREQUAL "python")
  run(${CMAKE_COMMAND} -E env PYTHONPATH=${PREFIX}/${PYDIR} --unset=WEARSCALE_DATA --unset=WEARSCALE_DATA_DIR
      ${PYTHON} -I -c "import sys; sys.path.insert(0, '${PREFIX}/${PYDIR}'); import wearscale, os; \
assert wearscale.__file__.startswith('${PREFIX}'), wearscale.__file__; \
d = wearscale.materials.data_directory(); print('data:', d); \
assert os.path.realpath(d) == os.path.realpath('${PREFIX}/share/wearscale/data'), d; \
print(wearscale.materials.interface_law('SiO2', 'Si')); \
r = wearscale.contact.hertz_check(32); print(r); assert r['approach_relative_error'] < 1e-3"
      WORKING_DIRECTORY ${PREFIX})
endif()
