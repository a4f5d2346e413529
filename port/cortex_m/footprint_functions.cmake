# Pieces of the footprint measurement shared by the Cortex-M boards' scripts
# (example/measure_footprint.cmake, ../stm32f405/firmware/measure_footprint.cmake),
# included in cmake -P mode. Expects SIZE (arm-none-eabi-size), OBJDUMP, STACK_TOOL
# (host/worst_case_stack) and QEMU (the toolchain's emulator command, a list) to be set.

# section_sizes(elf prefix): flash and RAM of an image (section_sizes.cmake).
include(${CMAKE_CURRENT_LIST_DIR}/section_sizes.cmake)

# QEMU comes as the toolchain's emulator command, which ends in -kernel.
list(GET QEMU -1 last)
if(last STREQUAL "-kernel")
  list(REMOVE_AT QEMU -1)
endif()

# Runs elf with -icount shift=0 (one instruction = 1 ns of virtual time) and reads the
# SysTick counts it prints: calibration_instructions, calibration_ticks, steady_updates,
# steady_ticks, as <prefix>_<key>.
function(run_timed elf prefix)
  execute_process(COMMAND ${QEMU} -icount shift=0 -kernel ${elf}
                  OUTPUT_VARIABLE output ERROR_VARIABLE output RESULT_VARIABLE status TIMEOUT 120)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${elf} under QEMU exited with ${status}:\n${output}")
  endif()
  foreach(key calibration_instructions calibration_ticks steady_updates steady_ticks)
    if(NOT output MATCHES "${key} ([0-9]+)")
      message(FATAL_ERROR "${elf} did not print ${key}:\n${output}")
    endif()
    set(${prefix}_${key} ${CMAKE_MATCH_1} PARENT_SCOPE)
  endforeach()
endfunction()

# The --ci options of the worst-case stack tool for every .ci file under the dirs.
function(ci_options out dirs)
  set(options)
  foreach(dir IN LISTS dirs)
    file(GLOB_RECURSE ci_files ${dir}/*.ci)
    foreach(f IN LISTS ci_files)
      list(APPEND options --ci ${f})
    endforeach()
  endforeach()
  set(${out} ${options} PARENT_SCOPE)
endfunction()

# From run_timed's with_* and without_* results (the image with the measured code and
# the same loop without it): <out> instructions per timed update, rounded; also
# instructions_per_tick ("d.ddd") and milli_instructions_per_tick. Fixed point with 3
# decimals: CMake's math() is integer only.
function(timed_difference out)
  if(NOT with_steady_updates EQUAL without_steady_updates OR with_calibration_ticks EQUAL 0)
    message(FATAL_ERROR "the two images did not time the same loop")
  endif()
  math(EXPR milli "${with_calibration_instructions} * 1000 / ${with_calibration_ticks}")
  math(EXPR update_milli "(${with_steady_ticks} - ${without_steady_ticks}) * ${milli} / ${with_steady_updates}")
  math(EXPR per_update "(${update_milli} + 500) / 1000")
  math(EXPR whole "${milli} / 1000")
  math(EXPR fraction "${milli} % 1000 + 1000")
  string(SUBSTRING ${fraction} 1 3 fraction)
  set(${out} ${per_update} PARENT_SCOPE)
  set(instructions_per_tick "${whole}.${fraction}" PARENT_SCOPE)
  set(milli_instructions_per_tick ${milli} PARENT_SCOPE)
endfunction()

# Disassembles elf into <output>, and reads it into <var>.
function(disassemble elf output var)
  execute_process(COMMAND ${OBJDUMP} -d --no-show-raw-insn ${elf} OUTPUT_FILE ${output} RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${OBJDUMP} -d ${elf} failed")
  endif()
  file(READ ${output} text)
  set(${var} "${text}" PARENT_SCOPE)
endfunction()

# Worst-case stack of a disassembled image from Reset_Handler, with the SysTick and fault
# handlers and the port's text output as an indirect call; ARGN adds options (more
# --indirect candidates, --report). Sets stack_report, stack_bytes, root_bytes and
# interrupt_bytes.
function(worst_case_stack disassembly ci_dirs)
  ci_options(ci "${ci_dirs}")
  execute_process(COMMAND ${STACK_TOOL} ${disassembly} ${ci}
                          --root Reset_Handler --interrupt SysTick_Handler --interrupt Fault_Handler
                          --indirect _ZN5aloft4port10write_textEPKc ${ARGN}
                  OUTPUT_VARIABLE report ERROR_VARIABLE error RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "worst-case stack: ${error}")
  endif()
  set(stack_report "${report}" PARENT_SCOPE)
  foreach(key stack_bytes root_bytes interrupt_bytes)
    string(REGEX MATCH "${key} ([0-9]+)" _ "${report}")
    set(${key} ${CMAKE_MATCH_1} PARENT_SCOPE)
  endforeach()
endfunction()

# <out> is "true" when value <= limit, else "false" (for footprint.json's targets_met).
function(verdict value limit out)
  if(value LESS_EQUAL limit)
    set(${out} "true" PARENT_SCOPE)
  else()
    set(${out} "false" PARENT_SCOPE)
  endif()
endfunction()
