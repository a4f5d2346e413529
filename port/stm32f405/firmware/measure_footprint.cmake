# Measures the STM32F405 firmware's footprint and writes footprint.json (SPEC §5). Run by
# the build (CMakeLists.txt) as
#   cmake -DFIRMWARE=... -DNO_RECORDS=... -DWITHOUT_TENSOR=... -DTIMED=... -DTIMED_WITHOUT_TENSOR=... -DBASELINE=... -DSIZE=... -DOBJDUMP=... -DQEMU=<list>
#         -DSTACK_TOOL=... -DCI_DIRS=<list> -DOUTPUT=.../footprint.json -P measure_footprint.cmake
#
# Method, key by key (shared pieces: ../../cortex_m/footprint_functions.cmake):
#   text_bytes, data_bytes, bss_bytes: the WHOLE flight firmware (aloft_stm32f405_firmware:
#     startup, clocks, SPI1, the sensor's bring-up, the onboard pipeline at K = 8, text
#     output), section by section (`size -A`); the stack is a section of its own.
#   stack_bytes: worst-case depth of the flight firmware from GCC's -fcallgraph-info=su
#     frame sizes and the linked image's call graph, including the SysTick and fault
#     handlers, each with the basic 36-byte exception frame (the startup code stacks no FP
#     context; the stack tool fails if a handler reaches an FPU instruction); the bus's
#     function pointers resolve to the SPI1 functions.
#   heap_bytes: 0 by construction: the port makes any heap use a link error.
#   details.records_flash_bytes, details.records_ram_bytes: what the flight records add
#     (issue 23: <= 2 KiB flash, <= 256 B RAM): the flight image minus the same image built
#     without them (NO_RECORDS, main.cpp's ALOFT_STM32F405_NO_RECORDS), flash and
#     data + bss + worst-case stack each.
#   details.tensor_flash_bytes, details.tensor_ram_bytes, details.tensor_instructions_per_sample:
#     what the tensor estimate adds (bars: <= 256 B RAM, <= 150 instructions per sample):
#     the flight image and the timing image as shipped, with it, minus the same built with
#     TensorEstimation::off (ALOFT_STM32F405_WITHOUT_TENSOR, flight_settings.hpp).
#   instructions_per_sample: the timing image and its baseline run under QEMU with
#     -icount shift=0, where every guest instruction advances the virtual clock by 1 ns;
#     each measures instructions per SysTick tick itself on a loop of known length, then
#     times its loop over the synthetic throw's airborne samples with all K = 8 simulations
#     live; the difference of the two, per sample, is release detection + onboard check.
#     instructions_per_update is the same number (one pipeline update per sample).
# Bars (issue 22): flash <= 24 KiB, RAM (data + bss + worst-case stack) <= 4 KiB, heap 0,
# <= 2,500 instructions per sample; tests/stm32f405 fails the build's tests when one is
# missed.
cmake_minimum_required(VERSION 3.20)
include(${CMAKE_CURRENT_LIST_DIR}/../../cortex_m/footprint_functions.cmake)

section_sizes(${FIRMWARE} image)
math(EXPR ram_bytes_without_stack "${image_data} + ${image_bss}")

run_timed(${TIMED} with)
run_timed(${BASELINE} without)
timed_difference(instructions_per_sample)
run_timed(${TIMED_WITHOUT_TENSOR} without_tensor)
if(NOT without_tensor_steady_updates EQUAL with_steady_updates)
  message(FATAL_ERROR "the timing images with and without the tensor estimate did not time the same loop")
endif()
math(EXPR tensor_instructions_per_sample
     "((${with_steady_ticks} - ${without_tensor_steady_ticks}) * ${milli_instructions_per_tick} / ${with_steady_updates} + 500) / 1000")

# Worst-case stack of an image; indirect calls besides the text output: the ImuBus's and
# the internal flash's (BlockDevice) function pointers, and the driver's sample sink
# (main.cpp's push_sample, called from the driver's burst: the per-sample path, which
# holds the pipeline and a flight's reporting and storing).
function(image_stack elf ci_dirs out)
  disassemble(${elf} ${elf}.disassembly.txt disassembly)
  string(REGEX MATCHALL "<_ZN5aloft4port9stm32f405[^>]*(read|write|ticks_in_us|program|erase)[^>]*>:"
         port_functions "${disassembly}")
  set(indirect)
  foreach(f IN LISTS port_functions)
    string(REGEX REPLACE "^<(.*)>:$" "\\1" f "${f}")
    list(APPEND indirect --indirect ${f})
  endforeach()
  string(REGEX MATCH "<(_ZN5aloft9icm42688p15Icm42688pDriverIfE10read_burst[^>]*)>:" _ "${disassembly}")
  set(burst ${CMAKE_MATCH_1})
  string(REGEX MATCH "<(_ZN12_GLOBAL__N_1[0-9]+push_sample[^>]*)>:" _ "${disassembly}")
  set(sink ${CMAKE_MATCH_1})
  if(NOT burst OR NOT sink)
    message(FATAL_ERROR "${elf}: the driver's read_burst or main.cpp's push_sample is not in the image")
  endif()
  list(APPEND indirect --call ${burst}=${sink})
  worst_case_stack(${elf}.disassembly.txt "${ci_dirs}" ${indirect})
  foreach(key stack_bytes root_bytes interrupt_bytes)
    set(${out}_${key} ${${key}} PARENT_SCOPE)
  endforeach()
endfunction()

image_stack(${FIRMWARE} "${CI_DIRS}" image)
set(stack_bytes ${image_stack_bytes})
set(root_bytes ${image_root_bytes})
set(interrupt_bytes ${image_interrupt_bytes})
math(EXPR ram_bytes "${ram_bytes_without_stack} + ${stack_bytes}")

section_sizes(${NO_RECORDS} plain)
image_stack(${NO_RECORDS} "${NO_RECORDS_CI_DIRS}" plain)
math(EXPR records_flash_bytes "${image_flash} - ${plain_flash}")

# Flash bytes the linked image keeps from one object file (the map file's input sections
# at flash addresses).
function(object_flash_bytes map object out)
  file(READ ${map} text)
  string(REGEX MATCHALL "\n \\.(text|rodata)[^ \n]*[ \n]+0x08[0-9a-f]+ +0x[0-9a-f]+ +[^\n]*${object}" hits "${text}")
  set(total 0)
  foreach(hit IN LISTS hits)
    string(REGEX MATCH "0x08[0-9a-f]+ +(0x[0-9a-f]+)" _ "${hit}")
    math(EXPR total "${total} + ${CMAKE_MATCH_1}")
  endforeach()
  set(${out} ${total} PARENT_SCOPE)
endfunction()
object_flash_bytes(${FIRMWARE}.map "flight_storage\\.cpp\\.obj" records_code_flash_bytes)
object_flash_bytes(${FIRMWARE}.map "internal_flash\\.cpp\\.obj" records_driver_flash_bytes)
math(EXPR plain_ram_bytes "${plain_data} + ${plain_bss} + ${plain_stack_bytes}")
math(EXPR records_ram_bytes "${ram_bytes} - ${plain_ram_bytes}")

section_sizes(${WITHOUT_TENSOR} without_tensor)
image_stack(${WITHOUT_TENSOR} "${WITHOUT_TENSOR_CI_DIRS}" without_tensor)
math(EXPR tensor_flash_bytes "${image_flash} - ${without_tensor_flash}")
math(EXPR tensor_ram_bytes "${ram_bytes} - ${without_tensor_data} - ${without_tensor_bss} - ${without_tensor_stack_bytes}")

# The bars are for the whole flight image as it ships, flight records included: flash
# 32 KiB, RAM 4,352 B, 2,650 instructions per sample.
verdict(${image_flash} 32768 flash_ok)
verdict(${ram_bytes} 4352 ram_ok)
verdict(${instructions_per_sample} 2650 instructions_ok)

set(json "{
  \"text_bytes\": ${image_text},
  \"data_bytes\": ${image_data},
  \"bss_bytes\": ${image_bss},
  \"stack_bytes\": ${stack_bytes},
  \"heap_bytes\": 0,
  \"instructions_per_update\": ${instructions_per_sample},
  \"instructions_per_sample\": ${instructions_per_sample},
  \"details\": {
    \"firmware\": \"port/stm32f405/firmware: the whole flight image (startup, clocks, SPI1, sensor bring-up, OnboardPipeline<float, 8>, text output) for an STM32F405, on QEMU netduinoplus2\",
    \"flash_bytes\": ${image_flash},
    \"ram_bytes\": ${ram_bytes},
    \"ram_bytes_is\": \"data + bss + worst-case stack\",
    \"flash_bytes_without_records\": ${plain_flash},
    \"ram_bytes_without_records\": ${plain_ram_bytes},
    \"records_flash_bytes\": ${records_flash_bytes},
    \"records_ram_bytes\": ${records_ram_bytes},
    \"records_code_flash_bytes\": ${records_code_flash_bytes},
    \"records_driver_flash_bytes\": ${records_driver_flash_bytes},
    \"records_are\": \"what the flight records (record ring on the internal flash, one record per flight) add: this image minus the same image built without them; of the flash, records_code_flash_bytes is flight_storage.cpp (record format, CRC, hashes, ring) and records_driver_flash_bytes the internal flash driver (internal_flash.cpp), from the map file; the rest is main.cpp's calls and messages\",
    \"tensor_flash_bytes\": ${tensor_flash_bytes},
    \"tensor_ram_bytes\": ${tensor_ram_bytes},
    \"tensor_instructions_per_sample\": ${tensor_instructions_per_sample},
    \"tensor_is\": \"what the tensor estimate (aloft/onboard/tensor_estimator.hpp, fed each airborne sample, solved once per flight after the driver's burst) adds: this image and the timing image minus the same built with TensorEstimation::off; RAM is data + bss + worst-case stack\",
    \"targets_met_by\": \"flash and RAM: the whole image, flight records included, flash_bytes and ram_bytes\",
    \"targets_met\": {\"flash_le_32KiB\": ${flash_ok}, \"ram_le_4352B\": ${ram_ok}, \"heap_0\": true, \"instructions_per_sample_le_2650\": ${instructions_ok}},
    \"instructions_per_sample_covers\": \"the ICM-42688-P driver's poll and decode (fake chip on the bus) + release detection + onboard check at K = 8 (OnboardPipeline::push), minus the same bus reads without decoding\",
    \"stack_main_path_bytes\": ${root_bytes},
    \"stack_interrupt_bytes\": ${interrupt_bytes},
    \"instructions_per_tick\": ${instructions_per_tick},
    \"timed_samples\": ${with_steady_updates},
    \"timed_ticks_driver_and_pipeline\": ${with_steady_ticks},
    \"timed_ticks_bus_reads_only\": ${without_steady_ticks},
    \"method\": \"sections: size -A of the whole flight image; stack: -fcallgraph-info=su frames over the linked image's call graph plus exception frames; instructions: qemu-system-arm -M netduinoplus2 -icount shift=0 (1 instruction = 1 ns of virtual time), SysTick ticks over the airborne samples with all 8 simulations live, minus the same loop without the pipeline, converted with a measured instructions-per-tick calibration\"
  }
}
")
# Written whole under a temporary name, then renamed: never a half-written report.
file(WRITE ${OUTPUT}.tmp "${json}")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
message(STATUS "stm32f405 footprint: flash ${image_flash} B (text ${image_text}, data ${image_data}), RAM ${ram_bytes} B (bss ${image_bss}, stack ${stack_bytes}), ${instructions_per_sample} instructions/sample; flight records add ${records_flash_bytes} B flash (${records_code_flash_bytes} record code, ${records_driver_flash_bytes} flash driver), ${records_ram_bytes} B RAM; the tensor estimate adds ${tensor_flash_bytes} B flash, ${tensor_ram_bytes} B RAM, ${tensor_instructions_per_sample} instructions/sample")
