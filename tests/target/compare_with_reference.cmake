# The example firmware's float answer against the host's double-precision one, on the same
# flight. Both print "key value" lines (port/cortex_m/example/main.cpp and
# host/reference_rms_da.cpp). Counts must agree exactly; rms_da_deg within
# RMS_DA_TOLERANCE_UDEG micro-degrees, rms_rel_err within REL_ERR_TOLERANCE_MICRO millionths.
#   cmake -DFIRMWARE_COMMAND=<list> -DREFERENCE_COMMAND=<list> -DRMS_DA_TOLERANCE_UDEG=N
#         -DREL_ERR_TOLERANCE_MICRO=N -P compare_with_reference.cmake
include(${CMAKE_CURRENT_LIST_DIR}/run_and_read.cmake)

# Sets PREFIX_samples, _seeds and _comparisons from `text`, and PREFIX_rms_da_deg and
# _rms_rel_err in millionths.
function(read_answer label text prefix)
  set(text "\n${text}\n")  # every key line now starts after a newline
  foreach(key samples seeds comparisons)
    if(NOT text MATCHES "\n${key} ([0-9]+)")
      message(FATAL_ERROR "${label} did not print ${key}")
    endif()
    set(${prefix}_${key} ${CMAKE_MATCH_1} PARENT_SCOPE)
  endforeach()
  # Six decimals each: read as integer millionths, since CMake has no floating point.
  foreach(key rms_da_deg rms_rel_err)
    if(NOT text MATCHES "\n${key} ([0-9]+)\\.([0-9][0-9][0-9][0-9][0-9][0-9])\n")
      message(FATAL_ERROR "${label} did not print ${key} with six decimals")
    endif()
    math(EXPR micro "${CMAKE_MATCH_1} * 1000000 + 1${CMAKE_MATCH_2} - 1000000")
    set(${prefix}_${key} ${micro} PARENT_SCOPE)
  endforeach()
endfunction()

run_and_read("firmware (float, QEMU)" "${FIRMWARE_COMMAND}" 120 target_output)
read_answer("firmware (float, QEMU)" "${target_output}" target)
run_and_read("host reference (double)" "${REFERENCE_COMMAND}" 120 host_output)
read_answer("host reference (double)" "${host_output}" host)

foreach(key samples seeds comparisons)
  if(NOT target_${key} EQUAL host_${key})
    message(FATAL_ERROR "${key}: firmware ${target_${key}}, host ${host_${key}}")
  endif()
endforeach()
if(host_comparisons EQUAL 0)
  message(FATAL_ERROR "no comparisons were made: nothing was checked")
endif()
math(EXPR da_difference "${target_rms_da_deg} - ${host_rms_da_deg}")
string(REPLACE "-" "" da_difference "${da_difference}")
math(EXPR rel_difference "${target_rms_rel_err} - ${host_rms_rel_err}")
string(REPLACE "-" "" rel_difference "${rel_difference}")
message("rms_da_deg differs by ${da_difference} micro-degrees (tolerance ${RMS_DA_TOLERANCE_UDEG}); "
        "rms_rel_err by ${rel_difference} millionths (tolerance ${REL_ERR_TOLERANCE_MICRO})")
if(da_difference GREATER RMS_DA_TOLERANCE_UDEG OR rel_difference GREATER REL_ERR_TOLERANCE_MICRO)
  message(FATAL_ERROR "firmware and host disagree beyond float tolerance")
endif()
