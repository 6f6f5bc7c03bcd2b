# wearscale_layer(NAME <name> DIR <folder> [NOT_KERNEL] [DEPENDS <layer>...] [LIBS <target>...])
#
# Adds the library of one architectural layer as `wearscale_<name>` with the
# alias `wearscale::<name>`. Its public headers live in <folder>/include and
# are visible only to the layer itself and to layers that declare it in
# DEPENDS: a solver that includes a coupling header fails to compile.
# NOT_KERNEL: a library without numerical kernels, compiled at -O1 in Release
# (cmake/WearscaleFlags.cmake).
# Installed (cmake/WearscaleInstall.cmake) as wearscale::<name> of find_package(wearscale).
include(GNUInstallDirs)

# wearscale_unity(<target>): compiles the target's sources in WEARSCALE_UNITY_BATCHES
# batches of equal size (one translation unit a batch) when WEARSCALE_UNITY is ON.
# Most sources are a few hundred lines behind the same standard-library, fmt and
# JSON headers: parsed once a batch instead of once a file. A source that cannot
# share a batch carries SKIP_UNITY_BUILD_INCLUSION, with the reason; the batch
# size is set at the end of the target's folder, once those marks are known, so
# that the batches come out even (30 sources in two batches: 15 and 15, not a
# batch of 8 and a batch of 1). Two batches keep two cores busy on the layers
# that build alone (core, materials, io, coupling, studies, the commands).
function(wearscale_unity target)
  if(WEARSCALE_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON)
    cmake_language(EVAL CODE "cmake_language(DEFER CALL _wearscale_unity_batch_size [[${target}]])")
  endif()
endfunction()

function(_wearscale_unity_batch_size target)
  get_target_property(sources ${target} SOURCES)
  set(n 0)
  foreach(s IN LISTS sources)
    get_source_file_property(skip ${s} SKIP_UNITY_BUILD_INCLUSION)
    if(s MATCHES "\\.cpp$" AND NOT skip)
      math(EXPR n "${n} + 1")
    endif()
  endforeach()
  # ceil(n / batches), and at least 6: a small library (materials, md, the
  # tribometer) is one batch, as a second would parse the same headers again
  # for two or three sources.
  math(EXPR size "(${n} + ${WEARSCALE_UNITY_BATCHES} - 1) / ${WEARSCALE_UNITY_BATCHES}")
  if(size LESS 6)
    set(size 6)
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD_BATCH_SIZE ${size})
endfunction()

function(wearscale_layer)
  cmake_parse_arguments(L "NOT_KERNEL" "NAME;DIR" "DEPENDS;LIBS" ${ARGN})
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${L_DIR}/src/*.cpp)
  add_library(wearscale_${L_NAME} STATIC ${sources})
  add_library(wearscale::${L_NAME} ALIAS wearscale_${L_NAME})
  target_include_directories(wearscale_${L_NAME} PUBLIC $<BUILD_INTERFACE:${L_DIR}/include>
                             $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}> PRIVATE ${L_DIR}/src)
  set(deps)
  foreach(d IN LISTS L_DEPENDS)
    list(APPEND deps wearscale::${d})
  endforeach()
  target_link_libraries(wearscale_${L_NAME} PUBLIC ${deps} ${L_LIBS} PRIVATE wearscale_flags)
  set_target_properties(wearscale_${L_NAME} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${L_NAME})
  wearscale_unity(wearscale_${L_NAME})
  if(L_NOT_KERNEL)
    set_target_properties(wearscale_${L_NAME} PROPERTIES WEARSCALE_NOT_KERNEL ON)
  endif()
  # Installed by cmake/WearscaleInstall.cmake: the library and its include/ folder as a whole.
  set_property(GLOBAL PROPERTY WEARSCALE_LAYER_${L_NAME}_DIR ${L_DIR})
  set_property(GLOBAL APPEND PROPERTY WEARSCALE_LAYERS ${L_NAME})
  set_property(GLOBAL PROPERTY WEARSCALE_LAYER_${L_NAME}_DEPENDS ${L_DEPENDS})
endfunction()
