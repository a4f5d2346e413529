# Does an image contain double-precision arithmetic? On a Cortex-M4F (single-precision
# FPU) every double operation is a libgcc soft-float call (__aeabi_d*, __aeabi_f2d,
# __adddf3, ...) or a double libm function (sin, atan2, sqrt, ...), so the symbol table
# tells. EXPECT=none passes only for an image free of them; EXPECT=some only for an image
# with them (the control that shows the check can fail).
#   cmake -DNM=arm-none-eabi-nm -DIMAGE=elf -DEXPECT=none|some -P no_double_check.cmake
execute_process(COMMAND ${NM} ${IMAGE} OUTPUT_VARIABLE symbols RESULT_VARIABLE status)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${NM} ${IMAGE} failed")
endif()
set(found "")
string(REPLACE "\n" ";" lines "${symbols}")
foreach(line IN LISTS lines)
  if(line MATCHES " [TtWw] ([A-Za-z0-9_]+)$")
    set(name ${CMAKE_MATCH_1})
    if(name MATCHES "^__aeabi_(d[a-z0-9]+|[a-z0-9]+2d|[a-z0-9]+2dz?)$"
       OR name MATCHES "^__[a-z]+df[0-9]?$"
       OR name MATCHES "^__ieee754_[a-z0-9_]*[^f]$"
       OR name MATCHES "^(sin|cos|tan|asin|acos|atan|atan2|sqrt|exp|log|pow|hypot|fmod|floor|ceil|fabs|round)$")
      list(APPEND found ${name})
    endif()
  endif()
endforeach()
list(LENGTH found count)
message("double-precision symbols in ${IMAGE}: ${count} ${found}")
if(EXPECT STREQUAL "none" AND count GREATER 0)
  message(FATAL_ERROR "the float build uses double precision: ${found}")
elseif(EXPECT STREQUAL "some" AND count EQUAL 0)
  message(FATAL_ERROR "expected double-precision symbols in ${IMAGE}; the check sees none")
endif()
