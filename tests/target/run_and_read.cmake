# run_and_read(LABEL COMMAND TIMEOUT_S RESULT), for the -P scripts that compare a firmware's
# answer with the host's: runs COMMAND (a list), prints what it said under LABEL, stops the
# script if it exits non-zero or outlasts TIMEOUT_S, and sets RESULT to its standard output,
# a newline, then its standard error (semihosting may write to either), with carriage
# returns removed, so every line it printed starts after a newline of its own.
function(run_and_read label command timeout_s result)
  execute_process(COMMAND ${command} OUTPUT_VARIABLE output ERROR_VARIABLE errors
                  RESULT_VARIABLE status TIMEOUT ${timeout_s})
  message("${label}:\n${output}${errors}")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${label} exited with ${status}")
  endif()
  string(REPLACE "\r" "" output "${output}\n${errors}")
  set(${result} "${output}" PARENT_SCOPE)
endfunction()
