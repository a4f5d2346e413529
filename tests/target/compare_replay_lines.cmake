# The replay firmware's result against the host's replay of the same CSV: both print the
# same "key value" lines per flight (port/cortex_m/replay_example/flight_lines.hpp), and
# every one must be equal, float results to the bit. At least one flight, with
# comparisons, must be there: an empty answer checks nothing.
#   cmake -DFIRMWARE_COMMAND=<list> -DHOST_COMMAND=<list> [-DKEYS=<list>] [-DREMOVE_FIRST=FILE]
#         [-DTARGET_READER=<list>] [-DREQUIRE_LINE=REGEX] -P compare_replay_lines.cmake
# KEYS replaces the keys compared; REMOVE_FIRST is deleted before the firmware runs (a file
# it writes, that the host command then reads). TARGET_READER, run after the firmware,
# prints the firmware's side instead of the firmware itself (a file it wrote, read back).
# REQUIRE_LINE: a line the firmware's side must hold (what makes the comparison count).
set(keys flight release_s landing_s samples gaps imu_position_from comparisons rms_da_deg rms_da_rad_bits
         rms_rel_err rms_rel_err_bits stream_samples stream_gaps)
if(DEFINED KEYS)
  set(keys ${KEYS})
endif()
if(DEFINED REMOVE_FIRST)
  file(REMOVE ${REMOVE_FIRST})
endif()
list(JOIN keys "|" key_pattern)

include(${CMAKE_CURRENT_LIST_DIR}/run_and_read.cmake)

# The lines of `text` that start with one of the keys, as a list.
function(key_lines text result)
  string(REPLACE "\n" ";" lines "${text}")
  set(kept)
  foreach(line IN LISTS lines)
    if(line MATCHES "^(${key_pattern}) ")
      list(APPEND kept "${line}")
    endif()
  endforeach()
  set(${result} "${kept}" PARENT_SCOPE)
endfunction()

run_and_read("firmware (float, QEMU)" "${FIRMWARE_COMMAND}" 240 target_output)
if(DEFINED TARGET_READER)
  run_and_read("what the firmware wrote, read back" "${TARGET_READER}" 240 target_output)
endif()
key_lines("${target_output}" target)
run_and_read("host replay (float, the code of aloft replay)" "${HOST_COMMAND}" 240 host_output)
key_lines("${host_output}" host)

if(NOT "${target}" MATCHES "(^|;)flight 0(;|$)")
  message(FATAL_ERROR "the firmware found no flight: nothing was checked")
endif()
if(DEFINED REQUIRE_LINE AND NOT "${target}" MATCHES "(^|;)${REQUIRE_LINE}(;|$)")
  message(FATAL_ERROR "no line \"${REQUIRE_LINE}\" on the firmware's side: nothing was checked")
endif()
if("${target}" MATCHES "(^|;)comparisons 0(;|$)")
  message(FATAL_ERROR "a flight without comparisons: its verdict checks nothing")
endif()
list(LENGTH target target_count)
list(LENGTH host host_count)
if(NOT target_count EQUAL host_count)
  message(FATAL_ERROR "firmware printed ${target_count} result lines, host ${host_count}")
endif()
math(EXPR last "${target_count} - 1")
foreach(i RANGE ${last})
  list(GET target ${i} t)
  list(GET host ${i} h)
  if(NOT t STREQUAL h)
    message(FATAL_ERROR "firmware \"${t}\", host \"${h}\"")
  endif()
endforeach()
message("all ${target_count} result lines equal")
