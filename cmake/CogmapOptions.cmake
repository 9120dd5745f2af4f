# Shared compile settings for every cogmap target.
include_guard(GLOBAL)

option(COGMAP_WERROR "Treat warnings as errors" ON)
option(COGMAP_SANITIZE "Build with AddressSanitizer and UndefinedBehaviorSanitizer" OFF)
option(COGMAP_BENCHMARKS "Build the Google Benchmark targets" ON)

if(NOT CMAKE_BUILD_TYPE AND NOT CMAKE_CONFIGURATION_TYPES)
  set(CMAKE_BUILD_TYPE RelWithDebInfo CACHE STRING "Build type" FORCE)
endif()

if(COGMAP_SANITIZE)
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=address,undefined)
endif()

# Applies warnings and the determinism flag to one target. -ffp-contract=off keeps
# floating point bit-identical whatever the optimiser fuses (same seed, same metrics).
function(cogmap_target_defaults target)
  target_compile_features(${target} PUBLIC cxx_std_20)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -ffp-contract=off)
  if(COGMAP_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
  # GCC 12 reports -Wrestrict inside libstdc++'s own std::string code at -O2/-O3 (GCC bug
  # 105651, fixed in 13): a false positive in a system header that -Werror would turn fatal.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
    target_compile_options(${target} PRIVATE -Wno-restrict)
  endif()
endfunction()

# cogmap_add_test(NAME name SOURCES ... LIBS ...): one GoogleTest executable, registered with ctest.
# PROPERTIES ... are added to every discovered test's properties (e.g. RUN_SERIAL TRUE).
# Every test may include tests/support (cogmap/test_support/scratch_dir.h: scratch folders).
function(cogmap_add_test)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS;PROPERTIES" ${ARGN})
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  cogmap_target_defaults(${ARG_NAME})
  target_include_directories(${ARG_NAME}
                             PRIVATE ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../tests/support)
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} GTest::gtest GTest::gtest_main)
  gtest_discover_tests(${ARG_NAME} DISCOVERY_TIMEOUT 60
                       PROPERTIES ENVIRONMENT "COGMAP_SOURCE_DIR=${PROJECT_SOURCE_DIR}"
                                  ${ARG_PROPERTIES})
endfunction()

# cogmap_add_benchmark(NAME name SOURCES ... LIBS ...): a Google Benchmark executable (not a test).
function(cogmap_add_benchmark)
  cmake_parse_arguments(ARG "" "NAME" "SOURCES;LIBS" ${ARGN})
  if(NOT COGMAP_BENCHMARKS)
    return()
  endif()
  find_package(benchmark QUIET)
  if(NOT benchmark_FOUND)
    message(STATUS "Google Benchmark not found: skipping ${ARG_NAME}")
    return()
  endif()
  add_executable(${ARG_NAME} ${ARG_SOURCES})
  cogmap_target_defaults(${ARG_NAME})
  target_link_libraries(${ARG_NAME} PRIVATE ${ARG_LIBS} benchmark::benchmark benchmark::benchmark_main)
endfunction()
