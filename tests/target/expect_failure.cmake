# ctest driver for an image that must fail: runs COMMAND (a list), and passes only if it
# exits with EXPECTED_STATUS and its output matches EXPECTED_OUTPUT (a regular expression).
# Plain WILL_FAIL would also pass on a crash or a hang; this does not.
#   cmake -DCOMMAND=... -DEXPECTED_STATUS=1 -DEXPECTED_OUTPUT=... -P expect_failure.cmake
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status OUTPUT_VARIABLE output
                ERROR_VARIABLE output TIMEOUT 120)
message("${output}")
if(NOT status STREQUAL EXPECTED_STATUS)
  message(FATAL_ERROR "exit status ${status}, expected ${EXPECTED_STATUS}")
endif()
if(NOT output MATCHES "${EXPECTED_OUTPUT}")
  message(FATAL_ERROR "output does not match: ${EXPECTED_OUTPUT}")
endif()
