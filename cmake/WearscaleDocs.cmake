# The manual as a site: the Markdown pages of docs/ (Sphinx with MyST) and the
# C++ API reference (Breathe over Doxygen's XML of the public headers,
# */include/wearscale/**).
#
#   cmake --build build --target docs     -> build/docs/html/index.html
#   ctest --test-dir build -L docs        -> docs.build (sphinx-build -W),
#                                            docs.no_journal (no dated entries) and
#                                            docs.commands (the manual's commands run)
#
# The target exists only when doxygen, sphinx-build and the Python modules
# myst_parser and breathe (importable by sphinx-build's own interpreter) are
# found (Debian: doxygen python3-sphinx python3-myst-parser python3-breathe);
# docs.build then skips, saying which is missing.

find_program(WEARSCALE_SPHINX_BUILD sphinx-build)
find_program(WEARSCALE_DOXYGEN doxygen)

set(WEARSCALE_DOCS_MISSING "")
if(NOT WEARSCALE_DOXYGEN)
  string(APPEND WEARSCALE_DOCS_MISSING "doxygen (Debian: doxygen); ")
endif()
if(NOT WEARSCALE_SPHINX_BUILD)
  string(APPEND WEARSCALE_DOCS_MISSING "sphinx-build (Debian: python3-sphinx); ")
else()
  # The interpreter sphinx-build runs under, from its #! line; fall back to
  # python3.
  file(STRINGS "${WEARSCALE_SPHINX_BUILD}" _ws_shebang LIMIT_COUNT 1)
  set(_ws_sphinx_python python3)
  if(_ws_shebang MATCHES "^#! *([^ ]+)")
    set(_ws_sphinx_python "${CMAKE_MATCH_1}")
  endif()
  foreach(_ws_module myst_parser breathe)
    execute_process(COMMAND "${_ws_sphinx_python}" -c "import ${_ws_module}"
                    RESULT_VARIABLE _ws_import OUTPUT_QUIET ERROR_QUIET)
    if(NOT _ws_import EQUAL 0)
      string(REPLACE "_" "-" _ws_debian "${_ws_module}")
      string(APPEND WEARSCALE_DOCS_MISSING
             "the Python module ${_ws_module} for ${_ws_sphinx_python} (Debian: python3-${_ws_debian}); ")
    endif()
  endforeach()
endif()

set(WEARSCALE_DOCS_DIR ${PROJECT_BINARY_DIR}/docs)
set(WEARSCALE_DOXYGEN_OUT ${WEARSCALE_DOCS_DIR}/doxygen)
file(GLOB WEARSCALE_DOXYGEN_DIRS LIST_DIRECTORIES true
     ${PROJECT_SOURCE_DIR}/*/include/wearscale
     ${PROJECT_SOURCE_DIR}/solvers/*/include/wearscale)
list(JOIN WEARSCALE_DOXYGEN_DIRS " " WEARSCALE_DOXYGEN_INPUT)
configure_file(${PROJECT_SOURCE_DIR}/docs/Doxyfile.in ${WEARSCALE_DOCS_DIR}/Doxyfile @ONLY)

# The Python API page reads the built module's docstrings.
set(WEARSCALE_DOCS_PYTHON_DIR "")
if(TARGET wearscale_python)
  set(WEARSCALE_DOCS_PYTHON_DIR ${PROJECT_BINARY_DIR}/python)
endif()

# One script builds the site, for the target and the test alike.
set(WEARSCALE_DOCS_BUILD_COMMAND
    sh ${PROJECT_SOURCE_DIR}/tests/docs/build_site.sh
    "${WEARSCALE_DOXYGEN}" "${WEARSCALE_SPHINX_BUILD}" ${WEARSCALE_DOCS_DIR}/Doxyfile
    ${WEARSCALE_DOXYGEN_OUT}/xml ${PROJECT_SOURCE_DIR}/docs ${WEARSCALE_DOCS_DIR}
    ${PROJECT_VERSION} "python_dir=${WEARSCALE_DOCS_PYTHON_DIR}" "missing=${WEARSCALE_DOCS_MISSING}")

if(WEARSCALE_DOCS_MISSING STREQUAL "")
  add_custom_target(docs
    COMMAND ${WEARSCALE_DOCS_BUILD_COMMAND}
    COMMENT "The manual: Doxygen's XML, then sphinx-build -W into ${WEARSCALE_DOCS_DIR}/html"
    VERBATIM)
  if(TARGET wearscale_python)
    add_dependencies(docs wearscale_python)
  endif()
else()
  message(STATUS "wearscale: no `docs` target; missing: ${WEARSCALE_DOCS_MISSING}")
endif()

if(WEARSCALE_BUILD_TESTS)
  add_test(NAME docs.build COMMAND ${WEARSCALE_DOCS_BUILD_COMMAND})
  set_tests_properties(docs.build PROPERTIES LABELS docs SKIP_RETURN_CODE 77 TIMEOUT 600
                       RESOURCE_LOCK wearscale_docs_site)
  find_program(WEARSCALE_DOCS_PYTHON NAMES python3)
  add_test(NAME docs.no_journal
           COMMAND ${WEARSCALE_DOCS_PYTHON} ${PROJECT_SOURCE_DIR}/tests/docs/no_journal.py
                   ${PROJECT_SOURCE_DIR})
  set_tests_properties(docs.no_journal PROPERTIES LABELS docs)
  # Comments say what the code is, not which issue or stop brought it.
  add_test(NAME docs.no_tracker_comments
           COMMAND ${WEARSCALE_DOCS_PYTHON} ${PROJECT_SOURCE_DIR}/tests/docs/no_tracker_comments.py
                   ${PROJECT_SOURCE_DIR})
  set_tests_properties(docs.no_tracker_comments PROPERTIES LABELS docs)
  # Every wearscale command of the README and the manual still runs as written
  # (a study's under --dry-run: its case and options checked, nothing computed).
  add_test(NAME docs.commands
           COMMAND ${WEARSCALE_DOCS_PYTHON} ${PROJECT_SOURCE_DIR}/tests/docs/commands.py
                   ${PROJECT_SOURCE_DIR} $<TARGET_FILE:wearscale>)
  set_tests_properties(docs.commands PROPERTIES LABELS docs TIMEOUT 900)
endif()
