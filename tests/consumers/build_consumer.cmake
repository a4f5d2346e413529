# Builds one consumer project (tests/consumers/<KIND>) from scratch and runs its ctest.
#   KIND           find_package or add_subdirectory
#   WORK_DIR       scratch folder (emptied first)
#   ALOFT_SOURCE   aloft's source tree; ALOFT_BUILD: its build tree (find_package installs it)
#   TOOLCHAIN      toolchain file, or empty for the host
#   GENERATOR      CMake generator
#   EXTRA_ARGS     more -D arguments for the consumer (optional)
#   NO_RUN         configure only
#   EXPECT_WARNING a regular expression the build's output must match (a warning that must
#                  fire, and not stop the build)
cmake_minimum_required(VERSION 3.20)

function(run_step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "consumer ${KIND}: ${what} failed (${status}):\n${out}")
  endif()
  message(STATUS "consumer ${KIND}: ${what} ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
set(configure_args -S ${ALOFT_SOURCE}/tests/consumers/${KIND} -B ${WORK_DIR}/build
                   -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release ${EXTRA_ARGS})
if(TOOLCHAIN)
  list(APPEND configure_args -DCMAKE_TOOLCHAIN_FILE=${TOOLCHAIN})
endif()

if(KIND STREQUAL "find_package")
  set(prefix ${WORK_DIR}/prefix)
  foreach(component core port)
    run_step("install of component ${component}"
      ${CMAKE_COMMAND} --install ${ALOFT_BUILD} --prefix ${prefix} --component ${component})
  endforeach()
  foreach(file include/aloft/onboard/onboard_check.hpp include/aloft_port/port.hpp
               lib/cmake/aloft/aloftConfig.cmake lib/cmake/aloft/aloftConfigVersion.cmake
               lib/cmake/aloft/aloftCoreTargets.cmake lib/cmake/aloft/aloftPortTargets.cmake)
    if(NOT EXISTS ${prefix}/${file})
      message(FATAL_ERROR "consumer ${KIND}: the install prefix has no ${file}")
    endif()
  endforeach()
  list(APPEND configure_args -DCMAKE_PREFIX_PATH=${prefix})
else()
  list(APPEND configure_args -DALOFT_SOURCE_DIR=${ALOFT_SOURCE})
endif()

run_step("configure" ${CMAKE_COMMAND} ${configure_args})
if(NO_RUN)
  return()
endif()
run_step("build" ${CMAKE_COMMAND} --build ${WORK_DIR}/build)
if(EXPECT_WARNING)
  if(NOT step_output MATCHES "${EXPECT_WARNING}")
    message(FATAL_ERROR "consumer ${KIND}: the build printed no warning matching "
                        "'${EXPECT_WARNING}', so it proves nothing:\n${step_output}")
  endif()
  message(STATUS "consumer ${KIND}: the warning fired and the build went on")
endif()
run_step("run" ${CMAKE_CTEST_COMMAND} --test-dir ${WORK_DIR}/build --output-on-failure)
message(STATUS "${step_output}")
