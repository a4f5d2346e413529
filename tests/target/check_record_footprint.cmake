# What the flight records add to a firmware image: probe 2 (the record ring in use) minus
# probe 1 (the same image with only the flash driver), from `size -A` (record_footprint_probe.cpp).
#   cmake -DSIZE=arm-none-eabi-size -DWITH=probe_2 -DWITHOUT=probe_1 -P check_record_footprint.cmake
# Flash: code, constants, vectors, unwind tables and .data's initial values; RAM: .data + .bss.
# Fails above issue 23's budget: 2 KiB of flash, 256 B of RAM.
include(${CMAKE_CURRENT_LIST_DIR}/../../port/cortex_m/section_sizes.cmake)
function(image_sizes elf flash_var ram_var)
  section_sizes(${elf} image)
  math(EXPR ram "${image_data} + ${image_bss}")
  set(${flash_var} ${image_flash} PARENT_SCOPE)
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
