# Runs highlight_lines_viewer on a script under xvfb-run, then highlight_lines_viewer_check on
# what it wrote. Variables: XVFB_RUN, VIEWER, CHECK, SCRIPT, MESH, OUT.
cmake_minimum_required(VERSION 3.16) # CMP0053: "@OUT@" is text, not a variable reference
set(radius 0.1)
set(iterations 3)
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
file(READ "${SCRIPT}" script)
string(REPLACE "@OUT@" "${OUT}" script "${script}")
string(REPLACE "@RADIUS@" "${radius}" script "${script}")
string(REPLACE "@ITERATIONS@" "${iterations}" script "${script}")
file(WRITE "${OUT}/session.script" "${script}")

execute_process(
  COMMAND "${XVFB_RUN}" -a -s "-screen 0 1024x768x24" "${VIEWER}" "${MESH}" --script
          "${OUT}/session.script" --size 800 600
  OUTPUT_VARIABLE output ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 100)
message("${output}${errors}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the viewer failed (${status})")
endif()

set(number "[-+0-9.eE]+")
if(NOT output MATCHES "pick: ray (${number}) (${number}) (${number}) direction (${number}) (${number}) (${number}) -> face")
  message(FATAL_ERROR "the viewer did not report its picking ray")
endif()
execute_process(
  COMMAND "${CHECK}" "${MESH}" "${OUT}" ${iterations} ${radius} ${CMAKE_MATCH_1} ${CMAKE_MATCH_2}
          ${CMAKE_MATCH_3} ${CMAKE_MATCH_4} ${CMAKE_MATCH_5} ${CMAKE_MATCH_6}
  RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the viewer's outputs differ from the library's (${status})")
endif()
