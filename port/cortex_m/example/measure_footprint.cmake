# Measures aloft's footprint in the example firmware and writes footprint.json (SPEC §5).
# Run by the build (CMakeLists.txt) as
#   cmake -DFIRMWARE=... -DBASELINE=... -DSIZE=... -DOBJDUMP=... -DQEMU=<list>
#         -DSTACK_TOOL=... -DCI_DIRS=<list> -DOUTPUT=.../footprint.json -P measure_footprint.cmake
#
# Method, key by key:
#   text_bytes, data_bytes, bss_bytes: the firmware minus the same program built without
#     aloft (ALOFT_EXAMPLE_WITHOUT_ALOFT), section by section (`size -A`): text counts
#     everything in flash but the initial values of .data (vectors, code, constants,
#     unwind tables, constructors); the stack is a section of its own and not counted.
#   stack_bytes: worst-case depth of the whole firmware from GCC's -fcallgraph-info=su
#     frame sizes and the call graph of the linked image (host/worst_case_stack.cpp),
#     including the SysTick and fault handlers, each with the basic 36-byte exception frame
#     (the startup code stacks no FP context; the stack tool fails if a handler reaches an
#     FPU instruction).
#   heap_bytes: 0 by construction: the cortex_m port makes any heap use a link error.
#   instructions_per_update: both images run under QEMU with -icount shift=0, where every
#     guest instruction advances the virtual clock by exactly 1 ns, so SysTick (25 MHz)
#     counts one tick per 40 instructions; the firmware measures that ratio itself on a
#     loop of known length. Each image times its loop over the flight from the first
#     sample with all K = 8 simulations live; the difference of the two, per sample, is one
#     onboard-check update (the loop's own load of the sample and dt is subtracted).
cmake_minimum_required(VERSION 3.20)

include(${CMAKE_CURRENT_LIST_DIR}/../footprint_functions.cmake)

section_sizes(${FIRMWARE} with)
section_sizes(${BASELINE} without)
math(EXPR text_bytes "${with_text} - ${without_text}")
math(EXPR data_bytes "${with_data} - ${without_data}")
math(EXPR bss_bytes "${with_bss} - ${without_bss}")
math(EXPR flash_bytes "${text_bytes} + ${data_bytes}")
math(EXPR ram_bytes "${data_bytes} + ${bss_bytes}")

run_timed(${FIRMWARE} with)
run_timed(${BASELINE} without)
timed_difference(instructions_per_update)
math(EXPR loop_milli "${without_steady_ticks} * ${milli_instructions_per_tick} / ${with_steady_updates}")
math(EXPR loop_instructions "(${loop_milli} + 500) / 1000")

disassemble(${FIRMWARE} ${OUTPUT}.disassembly.txt disassembly)
# The onboard check's per-sample work, where the compiler kept it out of line; else the
# update it was put in line into.
string(REGEX MATCH "<(_ZN5aloft12OnboardCheck[^>]*use_sample[^>]*)>:" _ "${disassembly}")
set(update_function ${CMAKE_MATCH_1})
if(NOT update_function)
  string(REGEX MATCH "<(_ZN5aloft12OnboardCheck[^>]*6update[^>]*)>:" _ "${disassembly}")
  set(update_function ${CMAKE_MATCH_1})
endif()
worst_case_stack(${OUTPUT}.disassembly.txt "${CI_DIRS}" --report "${update_function}")
set(update_stack_bytes null)
if(update_function AND stack_report MATCHES "below [^ ]+ ([0-9]+)")
  set(update_stack_bytes ${CMAKE_MATCH_1})
endif()
string(REGEX MATCHALL "path [^\n]+" path_lines "${stack_report}")
set(path_json "")
foreach(line IN LISTS path_lines)
  string(REGEX REPLACE "^path ([^ ]+) ([0-9]+) ([a-z]+)$" "{\"function\": \"\\1\", \"frame_bytes\": \\2, \"frame_from\": \"\\3\"}" item "${line}")
  if(path_json)
    string(APPEND path_json ",\n      ")
  endif()
  string(APPEND path_json "${item}")
endforeach()

verdict(${flash_bytes} 16384 flash_ok)
verdict(${ram_bytes} 2048 ram_ok)
verdict(${stack_bytes} 1024 stack_ok)
verdict(${instructions_per_update} 2000 instructions_ok)

set(json "{
  \"text_bytes\": ${text_bytes},
  \"data_bytes\": ${data_bytes},
  \"bss_bytes\": ${bss_bytes},
  \"stack_bytes\": ${stack_bytes},
  \"heap_bytes\": 0,
  \"instructions_per_update\": ${instructions_per_update},
  \"details\": {
    \"firmware\": \"port/cortex_m/example: OnboardCheck<float, 8>, seed every 10 samples, on QEMU mps2-an386 (Cortex-M4F)\",
    \"flash_bytes\": ${flash_bytes},
    \"ram_bytes\": ${ram_bytes},
    \"targets_met\": {\"flash_le_16KiB\": ${flash_ok}, \"ram_le_2KiB\": ${ram_ok}, \"stack_le_1KiB\": ${stack_ok}, \"instructions_le_2000\": ${instructions_ok}},
    \"image_with_aloft\": {\"text\": ${with_text}, \"data\": ${with_data}, \"bss\": ${with_bss}},
    \"image_without_aloft\": {\"text\": ${without_text}, \"data\": ${without_data}, \"bss\": ${without_bss}},
    \"stack_main_path_bytes\": ${root_bytes},
    \"stack_interrupt_bytes\": ${interrupt_bytes},
    \"stack_below_onboard_check_use_sample_bytes\": ${update_stack_bytes},
    \"stack_deepest_path\": [
      ${path_json}
    ],
    \"instructions_per_tick\": ${instructions_per_tick},
    \"timed_updates\": ${with_steady_updates},
    \"timed_ticks_with_aloft\": ${with_steady_ticks},
    \"timed_ticks_without_aloft\": ${without_steady_ticks},
    \"loop_instructions_per_sample_without_aloft\": ${loop_instructions},
    \"method\": \"sections: size -A of the firmware minus the same image built without aloft; stack: -fcallgraph-info=su frames over the linked image's call graph plus exception frames; instructions: qemu-system-arm -icount shift=0 (1 instruction = 1 ns of virtual time), SysTick ticks over the updates with all 8 simulations live, minus the same loop without aloft, converted with a measured instructions-per-tick calibration\"
  }
}
")
# Written whole under a temporary name, then renamed: never a half-written report.
file(WRITE ${OUTPUT}.tmp "${json}")
file(RENAME ${OUTPUT}.tmp ${OUTPUT})
message(STATUS "footprint: flash ${flash_bytes} B (text ${text_bytes}, data ${data_bytes}), RAM ${ram_bytes} B (bss ${bss_bytes}), stack ${stack_bytes} B, ${instructions_per_update} instructions/update")
