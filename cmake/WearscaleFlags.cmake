# Compiler flags, chosen deliberately:
#  -O3                 : vectorised loops over grids and particles.
#  -march=x86-64-v2    : SSE4.2/POPCNT baseline every x86 machine of the last
#                        decade has; portable binaries (CI, users, clusters).
#                        WEARSCALE_NATIVE=ON trades portability for AVX2/AVX-512.
#  no -ffast-math      : we test NaN detection and rely on IEEE semantics in
#                        convergence criteria; FFTW does its own SIMD anyway.
#  -fno-math-errno     : lets sqrt/floor inline; errno is never read here.
set(WEARSCALE_WARNINGS -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
    -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wnull-dereference
    -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
# GCC 12's -Wrestrict misfires inside libstdc++ on `"literal" + std::string`
# at -O3 (GCC bug 105651, fixed in GCC 13): silence that one false positive.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  list(APPEND WEARSCALE_WARNINGS -Wno-restrict)
endif()
# Clang reports `omp simd` loops it leaves scalar (e.g. under sanitizers):
# a performance note, not a defect.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  list(APPEND WEARSCALE_WARNINGS -Wno-pass-failed)
endif()

if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
  if(WEARSCALE_NATIVE)
    set(WEARSCALE_ARCH_FLAGS -march=native)
  else()
    set(WEARSCALE_ARCH_FLAGS -march=x86-64-v2 -mtune=generic)
  endif()
endif()

set(CMAKE_CXX_FLAGS_RELEASE "-O3 -DNDEBUG")
set(CMAKE_CXX_FLAGS_RELWITHDEBINFO "-O2 -g -DNDEBUG")

add_library(wearscale_flags INTERFACE)
target_compile_options(wearscale_flags INTERFACE
  $<$<COMPILE_LANGUAGE:CXX>:${WEARSCALE_WARNINGS} ${WEARSCALE_ARCH_FLAGS} -fno-math-errno>)

# Test programs (target property WEARSCALE_TEST_CODE, set by tests/CMakeLists.txt)
# at -O1 in Release: the physics they check runs in the libraries (-O3), and
# their gtest-heavy sources compiled about a third faster (measured: 17.6 → 11.3 s
# for test_config.cpp, 32.2 → 20.7 s for test_reliability_cli.cpp).
set(wearscale_test_code "$<BOOL:$<TARGET_PROPERTY:WEARSCALE_TEST_CODE>>")
target_compile_options(wearscale_flags INTERFACE $<$<AND:$<CONFIG:Release>,${wearscale_test_code}>:-O1>)

# Libraries that orchestrate and read and write files, not numerical kernels
# (target property WEARSCALE_NOT_KERNEL, set by wearscale_layer's NOT_KERNEL
# and on the command sources: md, io, coupling, studies, the commands) at -O1
# in Release: their compile time is mostly the optimiser working through
# fmt, JSON and standard-library templates, and -O2's extra passes (inlining
# of functions not marked inline, scheduling, partial redundancy elimination)
# took a quarter more CPU on their batches (measured: 20.0 s against 26.9 s for
# a studies batch) for a program whose time is spent in the kernels. The
# kernels (core, materials, bem, tribometer, dem, wear) stay at -O3. No
# -ffast-math and no FMA contraction at any level (-std=c++20, x86-64-v2):
# the same arithmetic, the same bits (docs/building.md gives the measurement).
set(wearscale_not_kernel "$<BOOL:$<TARGET_PROPERTY:WEARSCALE_NOT_KERNEL>>")
target_compile_options(wearscale_flags INTERFACE
  $<$<AND:$<CONFIG:Release>,${wearscale_not_kernel},$<NOT:${wearscale_test_code}>>:-O1>)

# Sanitizers: AddressSanitizer + UndefinedBehaviorSanitizer, every UB report
# fatal (so a finding fails its test instead of scrolling by).
# Test programs (target property WEARSCALE_TEST_CODE, set by tests/CMakeLists.txt)
# are compiled at -O0 with AddressSanitizer alone: UndefinedBehaviorSanitizer
# instruments the libraries, where the arithmetic under test lives, and on the
# gtest/gmock-heavy test sources it tripled the compile time of the sanitizer pass.
# Every program still links both runtimes.
if(WEARSCALE_SANITIZE OR WEARSCALE_FUZZ)
  target_compile_options(wearscale_flags INTERFACE -fsanitize=address -fno-omit-frame-pointer
    $<$<NOT:${wearscale_test_code}>:-fsanitize=undefined -fno-sanitize-recover=undefined>
    $<${wearscale_test_code}:-O0>)
  target_link_options(wearscale_flags INTERFACE -fsanitize=address,undefined -fno-sanitize-recover=undefined)
endif()
# Fuzzing (tests/fuzz): libFuzzer needs clang; every library is instrumented
# for coverage so the fuzzer can steer into the readers' branches.
if(WEARSCALE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "WEARSCALE_FUZZ needs clang (libFuzzer): configure with -DCMAKE_CXX_COMPILER=clang++ "
                        "-DCMAKE_C_COMPILER=clang (Debian: apt-get install clang libclang-rt-14-dev libomp-14-dev)")
  endif()
  target_compile_options(wearscale_flags INTERFACE -fsanitize=fuzzer-no-link)
endif()
