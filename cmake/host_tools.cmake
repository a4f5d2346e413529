# The firmware images' host tools (port/host_tools/) in a cross build, whose compiler
# targets the board. As LLVM builds its native tools for a cross build, this project is
# configured a second time, for the build machine: in ALOFT_HOST_TOOLS_DIR (host-tools/ of
# this build folder unless set), with the host's compiler and ALOFT_HOST_TOOLS_ONLY (lib/,
# port/'s headers and fakes, the few host_sim/ libraries the tools link, port/host_tools;
# no tests). The custom target
# aloft_host_tools, in `all`, builds there the tools the images asked for; that build
# follows host_sim/'s own CMakeLists.txt, so no source list is kept here.
#   aloft_host_tool(NAME...)  asks for tools; sets ALOFT_HOST_<NAME> (cache, for tests/)
#                             to the program, which a custom command may DEPEND on
#   aloft_build_host_tools()  configures the sub-build and adds aloft_host_tools: once,
#                             after every image asked (top-level CMakeLists.txt)
# The presets cortex-m4f and stm32f405 share one such build, build/host-tools: the tools
# and the host_sim/ libraries they link compile once for both (scripts/test.sh runs the
# stages one after the other; two builds sharing the folder must not run at once).
# The sub-build takes this build's CMAKE_COMPILE_WARNING_AS_ERROR and compiler launchers,
# and the host's compilers ALOFT_HOST_C_COMPILER and ALOFT_HOST_CXX_COMPILER (cc and c++
# found on the PATH unless set). They are passed explicitly: during a first configure
# CMake puts the cross compilers in the environment as CC and CXX, which the sub-build
# must not inherit.
include_guard(GLOBAL)
find_program(ALOFT_HOST_C_COMPILER NAMES cc gcc clang REQUIRED NO_CMAKE_FIND_ROOT_PATH
             DOC "C compiler of the host tools' native build")
find_program(ALOFT_HOST_CXX_COMPILER NAMES c++ g++ clang++ REQUIRED NO_CMAKE_FIND_ROOT_PATH
             DOC "C++ compiler of the host tools' native build")
set(ALOFT_HOST_TOOLS_DIR ${PROJECT_BINARY_DIR}/host-tools CACHE PATH
    "Build folder of the host tools' native build (may be shared by several cross builds)")

function(aloft_host_tool)
  foreach(name IN LISTS ARGN)
    set_property(GLOBAL APPEND PROPERTY ALOFT_HOST_TOOLS ${name})
    set(ALOFT_HOST_${name} ${ALOFT_HOST_TOOLS_DIR}/port/host_tools/${name}
        CACHE INTERNAL "host tool ${name}")
  endforeach()
endfunction()

function(aloft_build_host_tools)
  get_property(names GLOBAL PROPERTY ALOFT_HOST_TOOLS)
  if(NOT names)
    return()
  endif()
  list(REMOVE_DUPLICATES names)
  set(dir ${ALOFT_HOST_TOOLS_DIR})
  set(args -DALOFT_HOST_TOOLS_ONLY=ON -DCMAKE_BUILD_TYPE=Release -DCMAKE_C_COMPILER=${ALOFT_HOST_C_COMPILER}
           -DCMAKE_CXX_COMPILER=${ALOFT_HOST_CXX_COMPILER})
  foreach(var CMAKE_COMPILE_WARNING_AS_ERROR CMAKE_CXX_COMPILER_LAUNCHER CMAKE_C_COMPILER_LAUNCHER)
    if(DEFINED ${var})
      list(APPEND args "-D${var}=${${var}}")
    endif()
  endforeach()
  # Configured with every configure of this build (a second or so once set up); its own
  # build files rerun CMake when a CMakeLists.txt it reads changes.
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env --unset=CMAKE_TOOLCHAIN_FILE --unset=CC --unset=CXX
            ${CMAKE_COMMAND} -S ${PROJECT_SOURCE_DIR} -B ${dir} -G ${CMAKE_GENERATOR} ${args}
    RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "aloft: the host tools' native build (${dir}) failed to configure:\n${output}")
  endif()
  message(STATUS "aloft: host tools ${names} from the native build in ${dir}")
  set(targets)
  set(programs)
  foreach(name IN LISTS names)
    list(APPEND targets aloft_${name})
    list(APPEND programs ${ALOFT_HOST_${name}})
  endforeach()
  # Always run; the programs are byproducts, so what runs them reruns only when one changed.
  add_custom_target(aloft_host_tools ALL
    COMMAND ${CMAKE_COMMAND} --build ${dir} --target ${targets}
    BYPRODUCTS ${programs}
    COMMENT "Building the host tools (native build in ${dir})"
    USES_TERMINAL VERBATIM)
endfunction()
