# README.md and the pages under docs/ stay a manual a user reads:
# - README.md is at most 200 lines, every page docs/*.md at most 500, every page of measured
#   figures docs/validation/*.md at most 600;
# - no page names a commit (a word of 7-40 hex digits with a letter and a digit in it, not
#   written 0x...) or an issue ("issue 30", "Issue 30, item 4", "#30"): history lives in git;
# - every relative link [text](target) in README.md and docs/ resolves to an existing file
#   (anchors dropped; http(s) and mailto links are not followed);
# - the README's ```cpp block is EXAMPLE's text, verbatim.
#   cmake -DSOURCE=repo -DEXAMPLE=.../readme_firmware_example.cpp -P check_docs.cmake
cmake_minimum_required(VERSION 3.20)
set(failures "")

function(line_count file out)
  file(READ ${file} text)
  string(REGEX MATCHALL "\n" newlines "${text}")
  list(LENGTH newlines count)
  set(${out} ${count} PARENT_SCOPE)
endfunction()

file(GLOB_RECURSE pages ${SOURCE}/docs/*.md)
set(checked 0)
foreach(page ${SOURCE}/README.md ${pages})
  file(RELATIVE_PATH name ${SOURCE} ${page})
  if(name STREQUAL "README.md")
    set(limit 200)
  elseif(name MATCHES "^docs/validation/")
    set(limit 600)
  else()
    set(limit 500)
  endif()
  line_count(${page} count)
  if(count GREATER limit)
    string(APPEND failures "\n  ${name} has ${count} lines (at most ${limit})")
  endif()
  math(EXPR checked "${checked} + 1")

  # Commit hashes and issue numbers, line by line so that a failure names the line.
  file(READ ${page} text)
  # One list element a line: semicolons and brackets would split or group elements.
  string(REGEX REPLACE "[][;]" " " text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(number 0)
  foreach(line IN LISTS lines)
    math(EXPR number "${number} + 1")
    string(REGEX MATCHALL "[0-9A-Za-z_]*[0-9][0-9A-Za-z_]*" words "${line}")
    foreach(word IN LISTS words)
      string(LENGTH "${word}" length)
      if(length GREATER_EQUAL 7 AND length LESS_EQUAL 40 AND word MATCHES "^[0-9a-f]+$"
         AND word MATCHES "[a-f]")
        string(APPEND failures "\n  ${name}:${number}: '${word}' looks like a commit hash")
      endif()
    endforeach()
    if(line MATCHES "([Ii]ssues? #?[0-9]+|#[0-9]+)")
      string(APPEND failures "\n  ${name}:${number}: '${CMAKE_MATCH_1}' names an issue")
    endif()
  endforeach()
endforeach()

set(links 0)
foreach(page ${SOURCE}/README.md ${pages})
  get_filename_component(dir ${page} DIRECTORY)
  file(READ ${page} text)
  # Brackets would group a CMake list's elements: they become words first.
  string(REPLACE "[" "_OPEN_" text "${text}")
  string(REPLACE "]" "_CLOSE_" text "${text}")
  string(REGEX MATCHALL "_CLOSE_\\([^)#; ]+[^); ]*\\)" found "${text}")
  foreach(link IN LISTS found)
    string(REGEX REPLACE "^_CLOSE_\\(([^)#]*).*\\)$" "\\1" target "${link}")
    if(target MATCHES "^(https?|mailto):")
      continue()
    endif()
    math(EXPR links "${links} + 1")
    if(NOT EXISTS ${dir}/${target})
      file(RELATIVE_PATH name ${SOURCE} ${page})
      string(APPEND failures "\n  ${name}: link to ${target}, which does not exist")
    endif()
  endforeach()
endforeach()

file(READ ${SOURCE}/README.md readme)
file(READ ${EXAMPLE} example)
string(FIND "${readme}" "```cpp\n${example}```" at)
if(at EQUAL -1)
  string(APPEND failures "\n  README.md's ```cpp block is not ${EXAMPLE} verbatim")
endif()

if(failures)
  message(FATAL_ERROR "README.md and docs/:${failures}")
endif()
message("README.md and ${checked} pages: within their lengths, no commit hash or issue number; "
        "${links} relative links resolve")
