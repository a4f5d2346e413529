# Builds one target of this build tree and checks how its link ends.
#   EXPECT=success  the build must succeed;
#   EXPECT=heap     the build must fail, and with the cortex_m port's heap trap symbol
#                   (so a failure for any other reason does not count).
#   cmake -DBUILD_DIR=... -DTARGET=... -DEXPECT=success|heap -P expect_link.cmake
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BUILD_DIR} --target ${TARGET} -j 1
                OUTPUT_VARIABLE output ERROR_VARIABLE output RESULT_VARIABLE status)
message("${output}")
set(trap "undefined reference to `aloft_heap_use_is_a_link_error_on_cortex_m'")
string(FIND "${output}" "${trap}" trap_at)
if(EXPECT STREQUAL "success")
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${TARGET} should build and link, but the build failed")
  endif()
elseif(EXPECT STREQUAL "heap")
  if(status EQUAL 0)
    message(FATAL_ERROR "${TARGET} uses the heap, yet it linked")
  endif()
  if(trap_at EQUAL -1)
    message(FATAL_ERROR "${TARGET} failed to build, but not at the heap trap")
  endif()
  message("link failed at the heap trap, as it must")
else()
  message(FATAL_ERROR "EXPECT must be success or heap")
endif()
