# What the flight records add to a firmware image: probe 2 (the record ring in use) minus
# probe 1 (the same image with only the flash driver), from `size -A` (record_footprint_probe.cpp).
#   cmake -DSIZE=arm-none-eabi-size -DWITH=probe_2 -DWITHOUT=probe_1 -P check_record_footprint.cmake
# Flash: code, constants, vectors, unwind tables and .data's initial values; RAM: .data + .bss.
# Fails above issue 23's budget: 2 KiB of flash, 256 B of RAM.
function(image_sizes elf flash_var ram_var)
  execute_process(COMMAND ${SIZE} -A ${elf} OUTPUT_VARIABLE table RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${SIZE} -A ${elf} failed")
  endif()
  set(flash 0)
  set(ram 0)
  string(REPLACE "\n" ";" lines "${table}")
  foreach(line IN LISTS lines)
    if(line MATCHES "^(\\.[A-Za-z_.]+) +([0-9]+) +[0-9]+")
      set(name ${CMAKE_MATCH_1})
      set(bytes ${CMAKE_MATCH_2})  # saved: the next MATCHES resets CMAKE_MATCH_n
      if(name MATCHES "^\\.(isr_vector|text|rodata|ARM\\.extab|ARM\\.exidx|init_array)$")
        math(EXPR flash "${flash} + ${bytes}")
      elseif(name STREQUAL ".data")
        math(EXPR flash "${flash} + ${bytes}")
        math(EXPR ram "${ram} + ${bytes}")
      elseif(name STREQUAL ".bss")
        math(EXPR ram "${ram} + ${bytes}")
      endif()
    endif()
  endforeach()
  set(${flash_var} ${flash} PARENT_SCOPE)
  set(${ram_var} ${ram} PARENT_SCOPE)
endfunction()

image_sizes(${WITH} flash_with ram_with)
image_sizes(${WITHOUT} flash_without ram_without)
math(EXPR flash "${flash_with} - ${flash_without}")
math(EXPR ram "${ram_with} - ${ram_without}")
message(STATUS "flight records add ${flash} bytes of flash and ${ram} bytes of RAM")
if(flash GREATER 2048 OR ram GREATER 256)
  message(FATAL_ERROR "flight records over budget: ${flash} B flash (max 2048), ${ram} B RAM (max 256)")
endif()
