# How a test is registered, so each CI stage runs what it should (docs/architecture.md,
# "Tests and CI stages"). One mechanism for slow and statistical tests: the label `slow`.
# The `host` test preset runs every test; the `quick` preset (scripts/test.sh --quick) and
# the sanitizer stage (`host-asan`) leave out the label `slow`.
#
#   aloft_slow_test(NAME name COST seconds COMMAND cmd... SMALL_COMMAND cmd...
#                   [SMALL_COST seconds])
#       name        the whole test, labelled `slow`: run once, in the gcc host stage
#       name_small  one small case of it (a Catch2 filter, or a small size), run in every
#                   stage, so the sanitizers still go through the slow test's code;
#                   SMALL_COST, its seconds under the sanitizers, where it is longest
#   aloft_catch_test_per_file(NAME name TARGET target COST seconds...
#                             [SLOW file... SMALL_COMMAND cmd...])
#       one ctest entry per test_<file>.cpp of a Catch2 program, name_<file> (its test
#       cases, through Catch2's file-name tags), so that `ctest -j2` shares a long program
#       between the two cores; COST gives each file's seconds, in the order of the
#       target's sources. The files SLOW names are labelled `slow`, and name_small runs
#       SMALL_COMMAND, one small case of them
#   aloft_label_slow(name seconds)
#       labels a test registered by hand `slow`, with its COST; its small case, which
#       every stage runs, is registered beside it
#   aloft_test_cost(name seconds)
#       ctest starts the costly tests first under -j. COST is the seconds measured in
#       the stage where the test is longest (the gcc host stage for the slow tests, the
#       sanitizer stage for the small cases); once a build folder has run a test, ctest's own
#       Testing/Temporary/CTestCostData.txt takes over
#
# A Catch2 small case passes -w NoTests: a filter that matches no test case then fails the
# run, so a renamed test case cannot leave a small case empty.
include_guard(GLOBAL)

function(aloft_test_cost name seconds)
  set_tests_properties(${name} PROPERTIES COST ${seconds})
endfunction()

function(aloft_slow_test)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;COST;SMALL_COST" "COMMAND;SMALL_COMMAND")
  if(NOT arg_NAME OR NOT arg_COMMAND OR NOT arg_SMALL_COMMAND OR "${arg_COST}" STREQUAL "")
    message(FATAL_ERROR "aloft_slow_test: NAME, COST, COMMAND and SMALL_COMMAND are required")
  endif()
  add_test(NAME ${arg_NAME} COMMAND ${arg_COMMAND})
  aloft_label_slow(${arg_NAME} ${arg_COST})
  add_test(NAME ${arg_NAME}_small COMMAND ${arg_SMALL_COMMAND})
  if(arg_SMALL_COST)
    aloft_test_cost(${arg_NAME}_small ${arg_SMALL_COST})
  endif()
endfunction()

function(aloft_label_slow name seconds)
  set_property(TEST ${name} APPEND PROPERTY LABELS slow)
  aloft_test_cost(${name} ${seconds})
endfunction()

function(aloft_catch_test_per_file)
  cmake_parse_arguments(PARSE_ARGV 0 arg "" "NAME;TARGET" "COST;SLOW;SMALL_COMMAND")
  if(arg_SLOW AND NOT arg_SMALL_COMMAND)
    message(FATAL_ERROR "aloft_catch_test_per_file(${arg_NAME}): SLOW needs a SMALL_COMMAND")
  endif()
  get_target_property(sources ${arg_TARGET} SOURCES)
  list(LENGTH arg_COST cost_count)
  set(index 0)
  set(files)
  foreach(source IN LISTS sources)
    get_filename_component(stem ${source} NAME_WE)
    if(NOT stem MATCHES "^test_")
      continue()
    endif()
    if(index GREATER_EQUAL cost_count)
      message(FATAL_ERROR "aloft_catch_test_per_file(${arg_NAME}): no COST for ${source}")
    endif()
    list(GET arg_COST ${index} cost)
    math(EXPR index "${index} + 1")
    string(REGEX REPLACE "^test_" "" file ${stem})
    list(APPEND files ${file})
    # The file's test cases, hidden ones ([.]) left out; none matched fails (-w NoTests).
    add_test(NAME ${arg_NAME}_${file} COMMAND ${arg_TARGET} "-#" "[#${stem}]~[.]" -w NoTests)
    if(file IN_LIST arg_SLOW)
      aloft_label_slow(${arg_NAME}_${file} ${cost})
    else()
      aloft_test_cost(${arg_NAME}_${file} ${cost})
    endif()
  endforeach()
  if(NOT index EQUAL cost_count)
    message(FATAL_ERROR "aloft_catch_test_per_file(${arg_NAME}): ${cost_count} costs for ${index} files")
  endif()
  foreach(file IN LISTS arg_SLOW)
    if(NOT file IN_LIST files)
      message(FATAL_ERROR "aloft_catch_test_per_file(${arg_NAME}): SLOW ${file}: no test_${file}.cpp")
    endif()
  endforeach()
  if(arg_SLOW)
    add_test(NAME ${arg_NAME}_small COMMAND ${arg_SMALL_COMMAND})
  endif()
endfunction()
