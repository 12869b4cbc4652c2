# One place that sets the language level and warnings for every slamsweep target,
# so that a CI build (SLAMSWEEP_WERROR=ON) and a developer build differ only in -Werror.
function(slamsweep_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
  if(SLAMSWEEP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# A GoogleTest executable registered with ctest. The shared data folder is passed in
# so tests can find ../shared without depending on the working directory.
function(slamsweep_add_test name)
  cmake_parse_arguments(ARG "" "TIMEOUT;NOT_INSTRUMENTED" "SOURCES;LIBS" ${ARGN})
  if(ARG_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "slamsweep_add_test(${name}): unexpected '${ARG_UNPARSED_ARGUMENTS}' (a ';' in a reason splits it)")
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 600)
  endif()
  add_executable(${name} ${ARG_SOURCES})
  slamsweep_target_defaults(${name})
  set_target_properties(${name} PROPERTIES UNITY_BUILD ${SLAMSWEEP_UNITY_TESTS})
  target_link_libraries(${name} PRIVATE ${ARG_LIBS} slamsweep_test_support GTest::gtest GTest::gmock GTest::gtest_main)
  # NOT_INSTRUMENTED "reason": in a sanitizer build every discovered case is labelled `not_instrumented` and
  # the program is listed with the reason (slamsweep_not_instrumented does this for tests named in CMake).
  set(labels "")
  if(ARG_NOT_INSTRUMENTED AND SLAMSWEEP_SANITIZE)
    set(labels LABELS not_instrumented)
    file(APPEND "${SLAMSWEEP_NOT_INSTRUMENTED_FILE}" "${name} (every case): ${ARG_NOT_INSTRUMENTED}\n")
  endif()
  gtest_discover_tests(${name} DISCOVERY_TIMEOUT 60 PROPERTIES TIMEOUT ${ARG_TIMEOUT} ${labels})
endfunction()
