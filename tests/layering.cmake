# Fails if a layer includes a header of a layer it must not depend on
# (docs/architecture.md, docs/architecture-runner.md): core includes nothing above it; materials
# only core; the solvers (bem, dem, md, wear, tribometer) neither coupling nor
# studies, and no case reader (core/config.hpp: solvers take plain structs;
# the [md] keys are read in coupling/shear_test_keys.cpp); coupling not
# studies. Every library folder is covered.
set(above_core "materials|bem|dem|md|wear|tribometer|coupling|studies")
set(rules
  "core|wearscale/(${above_core})/"
  "materials|wearscale/(bem|dem|md|wear|tribometer|coupling|studies)/"
  "solvers/bem|wearscale/(coupling|studies)/|wearscale/core/config\\.hpp"
  "solvers/dem|wearscale/(coupling|studies)/|wearscale/core/config\\.hpp"
  "solvers/wear|wearscale/(coupling|studies)/|wearscale/core/config\\.hpp"
  "solvers/tribometer|wearscale/(coupling|studies)/|wearscale/core/config\\.hpp"
  "solvers/md|wearscale/(coupling|studies)/|wearscale/core/config\\.hpp"
  "coupling|wearscale/studies/")
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
if(violations)
  message(FATAL_ERROR "layering violations (see docs/architecture.md):\n${violations}")
endif()
