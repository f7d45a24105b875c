# One run of a command-line program checked on all it must do (run by ctest through
# sdf_add_refusal_test and sdf_add_run_test in CMakeLists.txt):
#
#   cmake -DEXPECT=refusal|success -DMESSAGE=<regex> -DOUTPUTS=<file>[,<file>...]
#         -P checkRun.cmake <program> [arg...]
#
# refusal: passes only when the program ends with a non-zero exit status (a crash or a
#          signal is not a refusal), its output (stdout and stderr) matches MESSAGE, and
#          none of OUTPUTS exists afterwards;
# success: exit status 0, the output matches MESSAGE, and every one of OUTPUTS written.
# OUTPUTS are removed before the run, so that a file left by an earlier run neither fails
# the test nor stands in for this one's. (ctest's PASS_REGULAR_EXPRESSION alone passes on
# the message whatever the exit status.)
foreach(required EXPECT MESSAGE OUTPUTS)
    if(NOT DEFINED ${required} OR "${${required}}" STREQUAL "")
        message(FATAL_ERROR "checkRun.cmake: -D${required}=... is required")
    endif()
endforeach()
if(NOT EXPECT MATCHES "^(refusal|success)$")
    message(FATAL_ERROR "checkRun.cmake: EXPECT ${EXPECT}: valid: refusal success")
endif()

# the command: every argument after the script's name
set(command "")
math(EXPR last "${CMAKE_ARGC} - 1")
foreach(i RANGE ${last})
    if(CMAKE_ARGV${i} STREQUAL "-P")
        math(EXPR first "${i} + 2")
        break()
    endif()
endforeach()
if(first LESS_EQUAL last)
    foreach(i RANGE ${first} ${last})
        string(REPLACE ";" "\\;" argument "${CMAKE_ARGV${i}}")   # one argument, not a list
        list(APPEND command "${argument}")
    endforeach()
endif()
if(NOT command)
    message(FATAL_ERROR "checkRun.cmake: no command after the script's name")
endif()

string(REPLACE "," ";" outputs "${OUTPUTS}")
foreach(file IN LISTS outputs)
    file(REMOVE "${file}")
endforeach()

execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")

set(failures "")
if(NOT status MATCHES "^[0-9]+$")
    string(APPEND failures "\n  the program did not exit normally: ${status}")
elseif(EXPECT STREQUAL refusal AND status EQUAL 0)
    string(APPEND failures "\n  exit status 0: the input was accepted")
elseif(EXPECT STREQUAL success AND NOT status EQUAL 0)
    string(APPEND failures "\n  exit status ${status}: the run failed")
endif()
if(NOT "${out}${err}" MATCHES "${MESSAGE}")
    string(APPEND failures "\n  the output does not match: ${MESSAGE}")
endif()
foreach(file IN LISTS outputs)
    if(EXPECT STREQUAL refusal AND EXISTS "${file}")
        string(APPEND failures "\n  output file written: ${file}")
    elseif(EXPECT STREQUAL success AND NOT EXISTS "${file}")
        string(APPEND failures "\n  output file not written: ${file}")
    endif()
endforeach()
if(failures)
    message(FATAL_ERROR "expected a ${EXPECT} (exit status ${status}):${failures}")
endif()
if(EXPECT STREQUAL refusal)
    message("refused: exit status ${status}, message matched, nothing written (${OUTPUTS})")
else()
    message("succeeded: exit status 0, message matched, written: ${OUTPUTS}")
endif()
