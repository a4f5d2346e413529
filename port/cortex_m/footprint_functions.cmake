# Pieces of the footprint measurement shared by the Cortex-M boards' scripts
# (example/measure_footprint.cmake, ../stm32f405/firmware/measure_footprint.cmake),
# included in cmake -P mode. Expects SIZE (arm-none-eabi-size) and QEMU (the toolchain's
# emulator command, a list) to be set.

# Flash and RAM of an image, section by section (`size -A`): <prefix>_text counts
# everything in flash but the initial values of .data (vectors, code, constants, unwind
# tables, constructors); <prefix>_flash adds them; the stack is a section of its own and
# not counted.
function(section_sizes elf prefix)
  execute_process(COMMAND ${SIZE} -A ${elf} OUTPUT_VARIABLE table RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${SIZE} -A ${elf} failed")
  endif()
  set(text 0)
  set(data 0)
  set(bss 0)
  string(REPLACE "\n" ";" lines "${table}")
  foreach(line IN LISTS lines)
    if(line MATCHES "^(\\.[A-Za-z_.]+) +([0-9]+) +[0-9]+")
      set(name ${CMAKE_MATCH_1})
      set(bytes ${CMAKE_MATCH_2})
      if(name MATCHES "^\\.(isr_vector|text|rodata|ARM\\.extab|ARM\\.exidx|init_array)$")
        math(EXPR text "${text} + ${bytes}")
      elseif(name STREQUAL ".data")
        math(EXPR data "${data} + ${bytes}")
      elseif(name STREQUAL ".bss")
        math(EXPR bss "${bss} + ${bytes}")
      endif()
    endif()
  endforeach()
  # .data's initial values are in flash too.
  math(EXPR flash "${text} + ${data}")
  set(${prefix}_text ${text} PARENT_SCOPE)
  set(${prefix}_data ${data} PARENT_SCOPE)
  set(${prefix}_bss ${bss} PARENT_SCOPE)
  set(${prefix}_flash ${flash} PARENT_SCOPE)
endfunction()

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
