# Fails if a layer includes a header of a layer it must not depend on
# (docs/architecture.md, docs/architecture-runner.md): core includes nothing above it; materials
# only core; the solvers (bem, dem, md, wear, tribometer) neither io (cases,
# HDF5, CSV: solvers take plain structs; the [md] keys are read in
# coupling/shear_test_keys.cpp) nor coupling nor studies; io not coupling nor
# studies; coupling not studies. Every library folder is covered.
# With -DLINKS=<file> (tests/CMakeLists.txt: each layer's link closure) it also
# fails if core, materials or a solver links HDF5 or toml++.
set(above_core "materials|bem|dem|md|wear|tribometer|io|coupling|studies")
set(rules
  "core|wearscale/(${above_core})/"
  "materials|wearscale/(bem|dem|md|wear|tribometer|io|coupling|studies)/"
  "solvers/bem|wearscale/(io|coupling|studies)/"
  "solvers/dem|wearscale/(io|coupling|studies)/"
  "solvers/wear|wearscale/(io|coupling|studies)/"
  "solvers/tribometer|wearscale/(io|coupling|studies)/"
  "solvers/md|wearscale/(io|coupling|studies)/"
  "io|wearscale/(coupling|studies)/"
  "coupling|wearscale/studies/")
# The DEM engine (solvers/dem/engine) includes none of the DEM experiments'
# headers (solvers/dem/experiments), though both sit under wearscale/dem/.
file(GLOB dem_experiments RELATIVE ${ROOT}/solvers/dem/experiments/include/wearscale/dem
     ${ROOT}/solvers/dem/experiments/include/wearscale/dem/*.hpp)
if(NOT dem_experiments)
  message(FATAL_ERROR "layering: no headers in ${ROOT}/solvers/dem/experiments (a folder was renamed: update tests/layering.cmake)")
endif()
list(TRANSFORM dem_experiments REPLACE "\\.hpp$" "")
list(JOIN dem_experiments "|" dem_experiments)
list(APPEND rules "solvers/dem/engine|wearscale/dem/(${dem_experiments})\\.hpp")
set(violations "")
foreach(rule IN LISTS rules)
  string(REPLACE "|" ";" parts "${rule}")
  list(GET parts 0 folder)
  list(SUBLIST parts 1 -1 pattern_parts)
  list(JOIN pattern_parts "|" pattern)
  if(NOT IS_DIRECTORY ${ROOT}/${folder})
    message(FATAL_ERROR "layering: no folder ${ROOT}/${folder} (a layer was renamed: update tests/layering.cmake)")
  endif()
  file(GLOB_RECURSE files ${ROOT}/${folder}/*.hpp ${ROOT}/${folder}/*.cpp)
  foreach(f IN LISTS files)
    file(STRINGS ${f} lines REGEX "#include [<\"](${pattern})")
    if(lines)
      string(APPEND violations "${f}: ${lines}\n")
    endif()
  endforeach()
endforeach()
if(DEFINED LINKS)
  if(NOT EXISTS ${LINKS})
    message(FATAL_ERROR "layering: no link closures in ${LINKS} (reconfigure the build)")
  endif()
  file(STRINGS ${LINKS} closures)
  set(checked 0)
  foreach(line IN LISTS closures)
    if(line MATCHES "^(core|materials|bem|dem|dem_engine|md|wear|tribometer): (.*)$")
      math(EXPR checked "${checked} + 1")
      set(layer ${CMAKE_MATCH_1})
      string(TOLOWER "${CMAKE_MATCH_2}" links)
      if(links MATCHES "(toml|hdf5)[^ ]*")
        string(APPEND violations "wearscale_${layer} links ${CMAKE_MATCH_0} (only io and above may)\n")
      endif()
    endif()
  endforeach()
  if(NOT checked EQUAL 8)
    message(FATAL_ERROR "layering: ${LINKS} lists ${checked} of the 8 layers below io")
  endif()
endif()
if(violations)
  message(FATAL_ERROR "layering violations (see docs/architecture.md):\n${violations}")
endif()
