# Host programs inside a cross build (the bare-metal presets): helpers that run on the
# build machine, compiled with the host's C++ compiler since this build's compiler targets
# the board. They may read JSON with nlohmann-json and use lib/ (in double) with Eigen.
#   aloft_add_host_tool(NAME SOURCE_DIR [INCLUDE_DIR...])
# builds SOURCE_DIR/NAME.cpp into ${CMAKE_CURRENT_BINARY_DIR}/host/NAME (target
# aloft_host_NAME, in `all`) and sets ALOFT_HOST_NAME to the program's path. Included once
# per build; a second call for the same NAME reuses the first program.
include_guard(GLOBAL)
find_program(ALOFT_HOST_CXX NAMES c++ g++ clang++ REQUIRED NO_CMAKE_FIND_ROOT_PATH)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
get_target_property(ALOFT_EIGEN_INCLUDE_DIRS Eigen3::Eigen INTERFACE_INCLUDE_DIRECTORIES)

function(aloft_add_host_tool name source_dir)
  if(TARGET aloft_host_${name})
    return()
  endif()
  set(tool_dir ${CMAKE_CURRENT_BINARY_DIR}/host)
  file(MAKE_DIRECTORY ${tool_dir})
  set(program ${tool_dir}/${name})
  set(includes)
  foreach(dir ${PROJECT_SOURCE_DIR}/lib/include ${source_dir} ${ARGN} ${ALOFT_EIGEN_INCLUDE_DIRS})
    list(APPEND includes -I${dir})
  endforeach()
  add_custom_command(OUTPUT ${program}
    COMMAND ${ALOFT_HOST_CXX} -std=c++17 -O2 -Wall -Wextra -Werror ${includes}
            -MD -MF ${program}.d -o ${program} ${source_dir}/${name}.cpp
    DEPENDS ${source_dir}/${name}.cpp
    DEPFILE ${program}.d
    COMMENT "Building host program ${name}"
    VERBATIM)
  add_custom_target(aloft_host_${name} ALL DEPENDS ${program})
  set(ALOFT_HOST_${name} ${program} CACHE INTERNAL "host program ${name}")
endfunction()
