# Fails if a layer includes a header of a layer it must not depend on
# (docs/architecture.md: solvers never include coupling/, core includes nothing above it).
set(rules
  "core|wearscale/(materials|bem|dem|wear|tribometer|coupling)/"
  "materials|wearscale/(bem|dem|wear|tribometer|coupling)/"
  "solvers|wearscale/coupling/")
set(violations "")
foreach(rule IN LISTS rules)
  string(REPLACE "|" ";" parts "${rule}")
  list(GET parts 0 folder)
  list(SUBLIST parts 1 -1 pattern_parts)
  list(JOIN pattern_parts "|" pattern)
  file(GLOB_RECURSE files ${ROOT}/${folder}/*.hpp ${ROOT}/${folder}/*.cpp)
  foreach(f IN LISTS files)
    file(STRINGS ${f} lines REGEX "#include [<\"]${pattern}")
    if(lines)
      string(APPEND violations "${f}: ${lines}\n")
    endif()
  endforeach()
endforeach()
if(violations)
  message(FATAL_ERROR "layering violations (see docs/architecture.md):\n${violations}")
endif()
