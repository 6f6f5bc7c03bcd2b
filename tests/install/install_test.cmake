# ctest install.*: `cmake --install` of the build tree into a scratch prefix,
# then (STEP=cxx) an external CMake project that find_package(wearscale)s it,
# links wearscale::bem and checks a Hertz contact, a program compiled with
# `c++ $(pkg-config --cflags --libs wearscale)` alone and run, the examples of the
# help and man page run from the installed tree (run_examples.sh), or (STEP=python) the
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

# The CLI's shell completions, and its man page when help2man made one (cmake/WearscaleCliDocs.cmake).
set(cli_docs share/bash-completion/completions/wearscale share/zsh/site-functions/_wearscale
    share/wearscale/cases/hertz_pin.toml share/wearscale/examples/python/_common.py)
if(EXISTS ${BUILD}/cli-docs/man1/wearscale.1)
  list(APPEND cli_docs share/man/man1/wearscale.1)
endif()
foreach(f IN LISTS cli_docs)
  if(NOT EXISTS ${PREFIX}/${f})
    message(FATAL_ERROR "cmake --install did not install ${f}")
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
  # pkg-config names the libraries and headers of the same prefix, and they are enough to
  # compile, link and run a program with the compiler alone (no CMake): pkgconfig_consumer.cpp.
  execute_process(COMMAND ${CMAKE_COMMAND} -E env PKG_CONFIG_PATH=${PREFIX}/lib/pkgconfig
                          pkg-config --cflags --libs wearscale
                  RESULT_VARIABLE rc OUTPUT_VARIABLE pc_flags ERROR_VARIABLE err OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "pkg-config --cflags --libs wearscale failed (${rc}): ${err}")
  endif()
  message("pkg-config --cflags --libs wearscale: ${pc_flags}")
  separate_arguments(pc_flags UNIX_COMMAND "${pc_flags}")  # as a shell splits $(pkg-config ...)
  # No -std= of its own: the flags carry the C++ standard the headers need (a compiler's default may be older).
  if(NOT pc_flags MATCHES "-std=c\\+\\+20")
    message(FATAL_ERROR "pkg-config --cflags wearscale does not give -std=c++20: ${pc_flags}")
  endif()
  run(${CXX} ${SOURCE}/tests/install/pkgconfig_consumer.cpp ${pc_flags} -o ${consumer}/pkgconfig_consumer)
  run(${CMAKE_COMMAND} -E env WEARSCALE_DATA=${PREFIX}/share/wearscale/data ${consumer}/pkgconfig_consumer)
  # The installed CLI runs and reads the shipped tables of its own prefix (run.h5 records the table's path).
  run(${CMAKE_COMMAND} -E env --unset=WEARSCALE_DATA --unset=WEARSCALE_DATA_DIR ${PREFIX}/bin/wearscale version)
  file(REMOVE_RECURSE ${consumer}/data-lookup)
  run(${CMAKE_COMMAND} -E env --unset=WEARSCALE_DATA --unset=WEARSCALE_DATA_DIR ${PREFIX}/bin/wearscale -q run
      ${SOURCE}/tests/install/data_lookup.toml --out ${consumer}/data-lookup)
  file(STRINGS ${consumer}/data-lookup/run.h5 tables REGEX "share/wearscale/data/thesis_fig9.18_Si.csv")
  string(FIND "${tables}" "${PREFIX}/share/wearscale/data/" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "the installed CLI did not read the data of ${PREFIX}: ${tables}")
  endif()
  # The help's and the man page's examples that name an example case run from the installed tree alone.
  run(bash ${SOURCE}/tests/install/run_examples.sh ${PREFIX} ${consumer}/examples)
elseif(STEP STREQUAL "python")
  # -I: neither PYTHONPATH nor the user's site-packages; the script puts the prefix's first.
  run(${CMAKE_COMMAND} -E env --unset=WEARSCALE_DATA --unset=WEARSCALE_DATA_DIR
      ${PYTHON} -I ${SOURCE}/tests/install/check_installed.py ${PREFIX} ${PYDIR} WORKING_DIRECTORY ${PREFIX})
endif()
