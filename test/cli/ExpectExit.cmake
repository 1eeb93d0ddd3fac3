# Runs one command and checks its exit code and its standard error (and, with EXPECT_STDOUT, its standard output).
#   cmake -DCMD="prog|arg1|arg2" -DEXPECT_CODE=2 -DEXPECT_REGEX="regex" [-DEXPECT_STDOUT="regex"] -P ExpectExit.cmake
# CMD separates arguments with '|'. A crash (signal) or a timeout reports a non-numeric result and fails.
string(REPLACE "|" ";" command "${CMD}")
execute_process(COMMAND ${command} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 15)
set(report "command: ${CMD}\nexit: ${code}\n--- stdout\n${out}\n--- stderr\n${err}")
if(NOT "${code}" STREQUAL "${EXPECT_CODE}")
  message(FATAL_ERROR "expected exit code ${EXPECT_CODE}\n${report}")
endif()
if(NOT "${err}" MATCHES "${EXPECT_REGEX}")
  message(FATAL_ERROR "standard error does not match '${EXPECT_REGEX}'\n${report}")
endif()
if(DEFINED EXPECT_STDOUT AND NOT "${out}" MATCHES "${EXPECT_STDOUT}")
  message(FATAL_ERROR "standard output does not match '${EXPECT_STDOUT}'\n${report}")
endif()
message(STATUS "ok: exit ${code}, stderr matches '${EXPECT_REGEX}'")
