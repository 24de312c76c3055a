# Configures, builds and runs the consumer project test/consumer in a fresh build directory:
# the package used from outside through CGAL::Highlight_lines, in one of two modes:
# - find_package: the repository is configured on its own (nothing but the library), installed
#   with `cmake --install` into <scratch dir>/install, and the consumer finds it there with
#   find_package(CGAL_Highlight_lines);
# - add_subdirectory: the consumer adds the repository; its cache is configured with its own
#   Release flags, and the script checks that they, and its build type, are left untouched.
#
#   cmake -DCONSUMER_SOURCE_DIR=<repo>/test/consumer -DCONSUMER_BINARY_DIR=<scratch dir>
#         [-DCONSUMER_MODE=find_package|add_subdirectory]
#         [-DCONSUMER_GENERATOR=<generator>] [-DCONSUMER_CXX_COMPILER=<compiler>]
#         [-DCONSUMER_BUILD_TYPE=Release] [-DCONSUMER_CGAL_DIR=<dir>]
#         [-DCONSUMER_EIGEN3_DIR=<dir>] -P run_consumer_test.cmake
#
# Any failing step (install, configure, build, check, run) makes the script fail with that
# step's output.
cmake_minimum_required(VERSION 3.16)

foreach(var CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer_test.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT CONSUMER_BUILD_TYPE)
  set(CONSUMER_BUILD_TYPE Release)
endif()
if(NOT CONSUMER_MODE)
  set(CONSUMER_MODE find_package)
endif()
get_filename_component(package_source_dir "${CONSUMER_SOURCE_DIR}/../.." ABSOLUTE)
# The consumer's own Release flags: in add_subdirectory mode the package must not replace them.
# -O0: the test checks that the package is found, compiles and links; unoptimised, the consumer
# compiles in half the time (it runs in a fraction of a second either way).
set(consumer_release_flags "-O0 -DNDEBUG -DHIGHLIGHT_LINES_CONSUMER_OWN_FLAGS")

# A fresh build directory: the test must see what a new user sees.
file(REMOVE_RECURSE "${CONSUMER_BINARY_DIR}")
file(MAKE_DIRECTORY "${CONSUMER_BINARY_DIR}")

set(common_args "-DCMAKE_BUILD_TYPE=${CONSUMER_BUILD_TYPE}")
if(CONSUMER_GENERATOR)
  list(APPEND common_args -G "${CONSUMER_GENERATOR}")
endif()
if(CONSUMER_CXX_COMPILER)
  list(APPEND common_args "-DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}")
endif()
if(CONSUMER_CGAL_DIR)
  list(APPEND common_args "-DCGAL_DIR=${CONSUMER_CGAL_DIR}")
endif()
if(CONSUMER_EIGEN3_DIR)
  list(APPEND common_args "-DEigen3_DIR=${CONSUMER_EIGEN3_DIR}")
endif()
set(consumer_build_dir "${CONSUMER_BINARY_DIR}/consumer")
set(configure_args -S "${CONSUMER_SOURCE_DIR}" -B "${consumer_build_dir}" ${common_args}
                   "-DHIGHLIGHT_LINES_CONSUMER_MODE=${CONSUMER_MODE}")

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  message("${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "consumer project: ${name} failed (${result})")
  endif()
endfunction()

if(CONSUMER_MODE STREQUAL "find_package")
  # The package as a user installs it: configured alone (only the library), then installed.
  set(package_build_dir "${CONSUMER_BINARY_DIR}/package")
  set(install_dir "${CONSUMER_BINARY_DIR}/install")
  run_step(
    "package configure" "${CMAKE_COMMAND}" -S "${package_source_dir}" -B "${package_build_dir}"
    ${common_args} -DHIGHLIGHT_LINES_BUILD_TESTS=OFF -DHIGHLIGHT_LINES_BUILD_EXAMPLES=OFF
    -DHIGHLIGHT_LINES_BUILD_BENCHMARKS=OFF -DHIGHLIGHT_LINES_BUILD_DOC=OFF)
  run_step("package install" "${CMAKE_COMMAND}" --install "${package_build_dir}" --prefix
           "${install_dir}")
  file(GLOB_RECURSE configs "${install_dir}/*/CGAL_Highlight_linesConfig*.cmake")
  list(LENGTH configs count)
  if(NOT EXISTS "${install_dir}/include/CGAL/compute_highlight_lines.h" OR NOT count EQUAL 2)
    message(FATAL_ERROR "consumer project: the installation lacks the headers or the package "
                        "configuration and version files (found: ${configs})")
  endif()
  list(APPEND configure_args "-DCMAKE_PREFIX_PATH=${install_dir}"
       "-DCMAKE_CXX_FLAGS_RELEASE=${consumer_release_flags}")
elseif(CONSUMER_MODE STREQUAL "add_subdirectory")
  list(APPEND configure_args "-DCMAKE_CXX_FLAGS_RELEASE=${consumer_release_flags}")
else()
  message(FATAL_ERROR "run_consumer_test.cmake: CONSUMER_MODE is find_package or "
                      "add_subdirectory, not '${CONSUMER_MODE}'")
endif()

run_step(configure "${CMAKE_COMMAND}" ${configure_args})

if(CONSUMER_MODE STREQUAL "add_subdirectory")
  # The consumer's cache after add_subdirectory() of the package: its own Release flags and
  # build type, and none of the package's tests, examples, benchmarks or docs switched on.
  file(STRINGS "${consumer_build_dir}/CMakeCache.txt" cache)
  foreach(entry "CMAKE_CXX_FLAGS_RELEASE:STRING=${consumer_release_flags}"
                "CMAKE_BUILD_TYPE:STRING=${CONSUMER_BUILD_TYPE}"
                "HIGHLIGHT_LINES_BUILD_TESTS:BOOL=OFF" "HIGHLIGHT_LINES_BUILD_EXAMPLES:BOOL=OFF"
                "HIGHLIGHT_LINES_BUILD_BENCHMARKS:BOOL=OFF" "HIGHLIGHT_LINES_BUILD_DOC:BOOL=OFF")
    list(FIND cache "${entry}" found)
    if(found EQUAL -1)
      message(FATAL_ERROR "consumer project: its cache has no '${entry}' after "
                          "add_subdirectory() of the package")
    endif()
  endforeach()
endif()

# One job: a CGAL translation unit needs about 1 GB to compile.
run_step(build "${CMAKE_COMMAND}" --build "${consumer_build_dir}" --parallel 1)

set(program "${consumer_build_dir}/consumer")
if(NOT EXISTS "${program}" AND EXISTS "${consumer_build_dir}/${CONSUMER_BUILD_TYPE}/consumer")
  set(program "${consumer_build_dir}/${CONSUMER_BUILD_TYPE}/consumer") # multi-config
endif()
run_step(run "${program}")
message(STATUS "consumer project (${CONSUMER_MODE}): configured, built and ran")
