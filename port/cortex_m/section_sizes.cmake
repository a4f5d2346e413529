# Flash and RAM of an image, section by section (`size -A`): <prefix>_text counts
# everything in flash but the initial values of .data (vectors, code, constants, unwind
# tables, constructors); <prefix>_flash adds them; the stack is a section of its own and
# not counted. The one reader of `size -A` for every footprint check of a Cortex-M image
# (footprint_functions.cmake, tests/target/check_record_footprint.cmake), in cmake -P
# mode, with SIZE (arm-none-eabi-size) set.
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
