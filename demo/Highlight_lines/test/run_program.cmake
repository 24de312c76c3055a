# Runs a command-line program for a test and checks what it did: fails if the program fails, if
# its output does not match EXPECT (a regular expression, optional), or if a file of FILES (a
# ;-separated list, optional) was not written.
#
#   cmake -DPROGRAM=<program> "-DARGS=<arg;arg;...>" [-DEXPECT=<regex>] [-DFILES=<file;...>]
#         -P run_program.cmake
foreach(file IN LISTS FILES)
  file(REMOVE "${file}")
endforeach()
execute_process(COMMAND "${PROGRAM}" ${ARGS} RESULT_VARIABLE result OUTPUT_VARIABLE output
                ERROR_VARIABLE output)
message("${output}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${PROGRAM} failed (${result})")
endif()
if(DEFINED EXPECT AND NOT output MATCHES "${EXPECT}")
  message(FATAL_ERROR "the output of ${PROGRAM} does not match '${EXPECT}'")
endif()
foreach(file IN LISTS FILES)
  if(NOT EXISTS "${file}")
    message(FATAL_ERROR "${PROGRAM} did not write ${file}")
  endif()
endforeach()
