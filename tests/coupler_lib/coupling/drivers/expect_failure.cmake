# Runs a command that must fail: non-zero exit status, EXPECT (a regex) printed exactly once,
# and done within 20 s (a hang detector, not a performance check).
#   cmake -DCMD="a|b|c" -DEXPECT="regex" -P expect_failure.cmake
string(REPLACE "|" ";" cmd "${CMD}")
string(TIMESTAMP t0 "%s")
execute_process(COMMAND ${cmd} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                TIMEOUT 20)
string(TIMESTAMP t1 "%s")
math(EXPR took "${t1} - ${t0}")
set(all "${out}${err}")
message("${all}")
message("exit status: ${rc}, wall time: ${took} s")
if("${rc}" MATCHES "timeout")
  message(FATAL_ERROR "the job did not end within 20 s (hang)")
endif()
if("${rc}" STREQUAL "0")
  message(FATAL_ERROR "expected a non-zero exit status")
endif()
# A ';' inside a match would split the list of matches: count with ';' replaced.
string(REPLACE ";" "," all_text "${all}")
string(REPLACE ";" "," expect "${EXPECT}")
string(REGEX MATCHALL "${expect}" hits "${all_text}")
list(LENGTH hits n)
if(NOT n EQUAL 1)
  message(FATAL_ERROR "expected the message '${EXPECT}' exactly once, found it ${n} times")
endif()
if(took GREATER_EQUAL 20)
  message(FATAL_ERROR "the job took ${took} s to end")
endif()
