# Sanitizer and fuzzing builds (docs/hostile-input.md). Both instrument every slamsweep target, so they
# are made in a build folder of their own:
#   -DSLAMSWEEP_SANITIZE=address,undefined   AddressSanitizer + UndefinedBehaviorSanitizer (GCC or clang)
#   -DSLAMSWEEP_FUZZ=ON                      clang only: the fuzz targets of tests/fuzz linked with libFuzzer,
#                                            everything else with its coverage (address,undefined by default)
# Libraries from Debian and the roster's upstream builds (scripts/install-slam.sh) stay uninstrumented.
set(SLAMSWEEP_SANITIZE "" CACHE STRING "Sanitizers for every slamsweep target (e.g. address,undefined)")
option(SLAMSWEEP_FUZZ "Build the fuzz targets with libFuzzer (clang; tests/fuzz)" OFF)

if(SLAMSWEEP_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "SLAMSWEEP_FUZZ needs clang (scripts/install-fuzz-deps.sh; CXX=clang++-14)")
  endif()
  if(NOT SLAMSWEEP_SANITIZE)
    set(SLAMSWEEP_SANITIZE "address,undefined" CACHE STRING "Sanitizers for every slamsweep target" FORCE)
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()

if(SLAMSWEEP_SANITIZE)
  string(REPLACE "," ";" sanitizers "${SLAMSWEEP_SANITIZE}")
  foreach(sanitizer IN LISTS sanitizers)
    if(NOT sanitizer MATCHES "^(address|undefined|leak)$")
      message(FATAL_ERROR "SLAMSWEEP_SANITIZE: '${sanitizer}' is not one of address, undefined, leak")
    endif()
  endforeach()
  # Every error stops the program (a test fails instead of printing and passing); line tables name the places.
  add_compile_options(-fsanitize=${SLAMSWEEP_SANITIZE} -fno-sanitize-recover=all -fno-omit-frame-pointer -g1)
  # -O1 (after the build type's -O3, so it wins): fewer calls inlined away, so a report's stack names the
  # functions it went through, at a speed the suite can still run at. The fuzz build keeps -O3 (executions/s).
  if(NOT SLAMSWEEP_FUZZ)
    add_compile_options(-O1)
  endif()
  # GCC 12's -Wmaybe-uninitialized misreads the instrumented code of libstdc++'s std::regex (its std::function
  # members "may be used uninitialized"): a warning, not an error, in sanitizer builds; other builds keep it.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    add_compile_options(-Wno-error=maybe-uninitialized)
  endif()
  add_link_options(-fsanitize=${SLAMSWEEP_SANITIZE})
  # The runtime options and the suppressions (third-party libraries only, each explained there) are compiled
  # into every program and module, so that a program started by a test, a job or another program has them.
  add_library(slamsweep_sanitizer_defaults STATIC ${CMAKE_CURRENT_LIST_DIR}/sanitizer_defaults.cc)
  link_libraries(slamsweep_sanitizer_defaults)
  add_link_options(-Wl,--undefined=__asan_default_options -Wl,--undefined=__lsan_default_suppressions
                   -Wl,--undefined=__asan_default_suppressions -Wl,--undefined=__ubsan_default_options)
  # Tests that cannot run instrumented are labelled (slamsweep_not_instrumented); the list is written here.
  set(SLAMSWEEP_NOT_INSTRUMENTED_FILE "${PROJECT_BINARY_DIR}/not-instrumented-tests.txt")
  file(WRITE "${SLAMSWEEP_NOT_INSTRUMENTED_FILE}" "")
endif()

# slamsweep_not_instrumented(TEST... REASON text): in a sanitizer build, labels the ctest tests
# `not_instrumented` (jobs/sanitize-check.sh leaves them out) and lists them with the reason in
# not-instrumented-tests.txt; in other builds it does nothing. Every such test is also listed in
# docs/hostile-input.md.
function(slamsweep_not_instrumented)
  cmake_parse_arguments(ARG "" "REASON" "TEST" ${ARGN})
  if(NOT SLAMSWEEP_SANITIZE)
    return()
  endif()
  if(NOT ARG_REASON)
    message(FATAL_ERROR "slamsweep_not_instrumented: say why (REASON)")
  endif()
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "slamsweep_not_instrumented: unexpected '${ARG_UNPARSED_ARGUMENTS}' (a ';' in a reason splits it)")
  endif()
  foreach(test IN LISTS ARG_TEST)
    set_property(TEST ${test} APPEND PROPERTY LABELS not_instrumented)
    file(APPEND "${SLAMSWEEP_NOT_INSTRUMENTED_FILE}" "${test}: ${ARG_REASON}\n")
  endforeach()
endfunction()
