# Runs a command and checks both its exit status and its output (CTest's
# PASS_REGULAR_EXPRESSION alone would ignore the exit status):
#   cmake -DCMD="a|b|c" -DEXIT=zero|nonzero -DEXPECT="regex" [-DONCE=1] [-DWITHIN=s]
#         -P expect_output.cmake
# ONCE: the message must appear exactly once (not once per rank). WITHIN: the job must end
# within that many seconds (a hang detector, not a performance check).
string(REPLACE "|" ";" cmd "${CMD}")
if(NOT DEFINED WITHIN)
  set(WITHIN 600)
endif()
string(TIMESTAMP t0 "%s")
execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT ${WITHIN})
string(TIMESTAMP t1 "%s")
math(EXPR took "${t1} - ${t0}")
set(all "${out}${err}")
message("${all}")
message("exit status: ${rc}, wall time: ${took} s")
if("${rc}" MATCHES "timeout")
  message(FATAL_ERROR "the job did not end within ${WITHIN} s (hang)")
endif()
if(EXIT STREQUAL "zero" AND NOT "${rc}" STREQUAL "0")
  message(FATAL_ERROR "expected exit status 0, got ${rc}")
elseif(EXIT STREQUAL "nonzero" AND "${rc}" STREQUAL "0")
  message(FATAL_ERROR "expected a non-zero exit status")
elseif(NOT EXIT MATCHES "^(zero|nonzero)$")
  message(FATAL_ERROR "expect_output.cmake: EXIT must be zero or nonzero, got '${EXIT}'")
endif()
# A ';' inside a match would split the list of matches: count with ';' replaced.
string(REPLACE ";" "," all_text "${all}")
string(REPLACE ";" "," expect "${EXPECT}")
string(REGEX MATCHALL "${expect}" hits "${all_text}")
list(LENGTH hits n)
if(ONCE AND NOT n EQUAL 1)
  message(FATAL_ERROR "expected the message '${EXPECT}' exactly once, found it ${n} times")
elseif(n EQUAL 0)
  message(FATAL_ERROR "expected the message '${EXPECT}' in the output")
endif()
if(took GREATER_EQUAL WITHIN)
  message(FATAL_ERROR "the job took ${took} s to end")
endif()
