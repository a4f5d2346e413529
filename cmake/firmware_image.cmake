# A bare-metal firmware image (cortex_m and stm32f405 ports): the one way every image of
# port/ and tests/target is made.
#   aloft_add_firmware_image(NAME SOURCES src... LINK lib... STACK_BYTES hex
#                            [FP_CONTRACT_OFF] [MEASURED_STACK])
#     the sources, linked with LINK (in that order: the object libraries aloft_port and
#     the board's are linked directly, as their objects do not pass on transitively), under
#     lib/'s strict flags with no heap (EIGEN_NO_MALLOC), the folder's own headers found,
#     a stack of STACK_BYTES (the linker script's __stack_size__) and a link map beside it.
#     FP_CONTRACT_OFF  no fused multiply-add contraction: the host's x86-64 float
#                      arithmetic has none, and the image's results are compared with the
#                      host's to the bit
#     MEASURED_STACK   frame sizes and call graphs (.su, .ci beside the objects) for the
#                      worst-case stack of footprint.json, compiled without ccache: it does
#                      not restore the -fcallgraph-info (.ci) files on a hit, and the stack
#                      would be read from an earlier build's frames
include_guard(GLOBAL)

function(aloft_add_firmware_image name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "FP_CONTRACT_OFF;MEASURED_STACK" "STACK_BYTES" "SOURCES;LINK")
  if(NOT arg_SOURCES OR NOT arg_LINK OR NOT arg_STACK_BYTES)
    message(FATAL_ERROR "aloft_add_firmware_image(${name}): SOURCES, LINK and STACK_BYTES are required")
  endif()
  add_executable(${name} ${arg_SOURCES})
  target_include_directories(${name} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_link_libraries(${name} PRIVATE ${arg_LINK})
  set(options ${ALOFT_STRICT_FLAGS})
  if(arg_FP_CONTRACT_OFF)
    list(APPEND options -ffp-contract=off)
  endif()
  if(arg_MEASURED_STACK)
    list(APPEND options -fstack-usage -fcallgraph-info=su)
    set_target_properties(${name} PROPERTIES CXX_COMPILER_LAUNCHER "" C_COMPILER_LAUNCHER "")
  endif()
  target_compile_options(${name} PRIVATE ${options})
  target_compile_definitions(${name} PRIVATE EIGEN_NO_MALLOC)
  target_link_options(${name} PRIVATE -Wl,--defsym=__stack_size__=${arg_STACK_BYTES}
                      -Wl,-Map=$<TARGET_FILE:${name}>.map)
endfunction()
