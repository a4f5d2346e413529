# The README's footprint table states what footprint.json measured: flash (text + data),
# RAM (bss), worst-case stack and instructions per update, each the first number of its
# row's "measured" cell ("7,500 B", "2,835").
#   cmake -DFOOTPRINT=.../footprint.json -DREADME=.../README.md -P readme_matches_footprint.cmake
file(READ ${FOOTPRINT} json)
string(JSON text GET "${json}" text_bytes)
string(JSON data GET "${json}" data_bytes)
string(JSON bss GET "${json}" bss_bytes)
string(JSON stack GET "${json}" stack_bytes)
string(JSON instructions GET "${json}" instructions_per_update)
math(EXPR flash "${text} + ${data}")

file(STRINGS ${README} rows REGEX "^\\| (flash|RAM|worst-case stack|instructions per onboard-check update)")
set(failures "")
foreach(pair "flash;${flash}" "RAM;${bss}" "worst-case stack;${stack}"
             "instructions per onboard-check update;${instructions}")
  list(GET pair 0 label)
  list(GET pair 1 measured)
  set(found "")
  foreach(row IN LISTS rows)
    if(row MATCHES "^\\| ${label}[^|]*\\| ([0-9,]+)")
      string(REPLACE "," "" found "${CMAKE_MATCH_1}")
    endif()
  endforeach()
  if(found STREQUAL "")
    string(APPEND failures "\n  no README row '${label}'")
  elseif(NOT found EQUAL measured)
    string(APPEND failures "\n  ${label}: README says ${found}, footprint.json ${measured}")
  endif()
endforeach()
if(failures)
  message(FATAL_ERROR "README's footprint table disagrees with ${FOOTPRINT}:${failures}")
endif()
message("README footprint table matches: flash ${flash}, RAM ${bss}, stack ${stack}, instructions ${instructions}")
