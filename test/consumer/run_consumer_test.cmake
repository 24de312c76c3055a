# Configures, builds and runs the consumer project test/consumer in a fresh build directory:
# the package used from outside, through add_subdirectory() and CGAL::Highlight_lines.
#
#   cmake -DCONSUMER_SOURCE_DIR=<repo>/test/consumer -DCONSUMER_BINARY_DIR=<scratch dir>
#         [-DCONSUMER_GENERATOR=<generator>] [-DCONSUMER_CXX_COMPILER=<compiler>]
#         [-DCONSUMER_BUILD_TYPE=Release] [-DCONSUMER_CGAL_DIR=<dir>]
#         [-DCONSUMER_EIGEN3_DIR=<dir>] -P run_consumer_test.cmake
#
# Any failing step (configure, build, run) makes the script fail with that step's output.
cmake_minimum_required(VERSION 3.16)

foreach(var CONSUMER_SOURCE_DIR CONSUMER_BINARY_DIR)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_consumer_test.cmake: ${var} is not set")
  endif()
endforeach()
if(NOT CONSUMER_BUILD_TYPE)
  set(CONSUMER_BUILD_TYPE Release)
endif()

# A fresh build directory: the test must see what a new user sees.
file(REMOVE_RECURSE "${CONSUMER_BINARY_DIR}")
file(MAKE_DIRECTORY "${CONSUMER_BINARY_DIR}")

set(configure_args -S "${CONSUMER_SOURCE_DIR}" -B "${CONSUMER_BINARY_DIR}"
                   "-DCMAKE_BUILD_TYPE=${CONSUMER_BUILD_TYPE}")
if(CONSUMER_GENERATOR)
  list(APPEND configure_args -G "${CONSUMER_GENERATOR}")
endif()
if(CONSUMER_CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CONSUMER_CXX_COMPILER}")
endif()
if(CONSUMER_CGAL_DIR)
  list(APPEND configure_args "-DCGAL_DIR=${CONSUMER_CGAL_DIR}")
endif()
if(CONSUMER_EIGEN3_DIR)
  list(APPEND configure_args "-DEigen3_DIR=${CONSUMER_EIGEN3_DIR}")
endif()

function(run_step name)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output
                  ERROR_VARIABLE output)
  message("${output}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "consumer project: ${name} failed (${result})")
  endif()
endfunction()

run_step(configure "${CMAKE_COMMAND}" ${configure_args})
# One job: a CGAL translation unit needs about 1 GB to compile.
run_step(build "${CMAKE_COMMAND}" --build "${CONSUMER_BINARY_DIR}" --parallel 1)

set(program "${CONSUMER_BINARY_DIR}/consumer")
if(NOT EXISTS "${program}" AND EXISTS "${CONSUMER_BINARY_DIR}/${CONSUMER_BUILD_TYPE}/consumer")
  set(program "${CONSUMER_BINARY_DIR}/${CONSUMER_BUILD_TYPE}/consumer") # multi-config
endif()
run_step(run "${program}")
message(STATUS "consumer project: configured, built and ran")
