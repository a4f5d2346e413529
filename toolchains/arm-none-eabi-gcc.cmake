# Bare-metal ARM toolchain (Debian gcc-arm-none-eabi with newlib), compiler part. The CPU
# flags live in cpu/<ALOFT_CPU>.cmake (TinyUSB style), so another Cortex-M is one new file.
# Used by the `cortex-m4f` preset: images run on QEMU's mps2-an386 board with semihosting.
# A board's own toolchain file sets ALOFT_PORT and ALOFT_QEMU_MACHINE first and includes
# this one (stm32f405-gcc.cmake).
set(CMAKE_SYSTEM_NAME Generic)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(ALOFT_CPU "cortex-m4f" CACHE STRING "CPU flags file in toolchains/cpu/")
set(ALOFT_PORT "cortex_m" CACHE STRING "Platform port: host, cortex_m, stm32f405 or linux_arm")
if(NOT ALOFT_QEMU_MACHINE)
  set(ALOFT_QEMU_MACHINE mps2-an386)
endif()
include(${CMAKE_CURRENT_LIST_DIR}/cpu/${ALOFT_CPU}.cmake)

set(CMAKE_C_COMPILER arm-none-eabi-gcc)
set(CMAKE_CXX_COMPILER arm-none-eabi-g++)
set(CMAKE_ASM_COMPILER arm-none-eabi-gcc)
# No OS to link a test program against while CMake probes the compiler.
set(CMAKE_TRY_COMPILE_TARGET_TYPE STATIC_LIBRARY)

# Sections per function and object so the linker drops what is unused (and the footprint
# counts only what runs); no exceptions, RTTI or thread-safe statics: firmware has none
# of their runtimes. -fno-use-cxa-atexit: nothing is ever destroyed at exit on a board,
# and newlib's atexit registry may reach for the heap. -fno-math-errno: firmware never reads
# errno, and without it sqrtf cannot be the FPU's single vsqrt instruction.
set(ALOFT_TARGET_COMMON_FLAGS
    "${ALOFT_CPU_FLAGS} -ffunction-sections -fdata-sections -fno-math-errno")
set(CMAKE_C_FLAGS_INIT "${ALOFT_TARGET_COMMON_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT
    "${ALOFT_TARGET_COMMON_FLAGS} -fno-exceptions -fno-rtti -fno-threadsafe-statics -fno-use-cxa-atexit")
set(CMAKE_ASM_FLAGS_INIT "${ALOFT_CPU_FLAGS}")
# newlib-nano; the port supplies the startup code (-nostartfiles) and the few system calls.
set(CMAKE_EXE_LINKER_FLAGS_INIT
    "${ALOFT_CPU_FLAGS} --specs=nano.specs -nostartfiles -Wl,--gc-sections")

# Images run on QEMU's model of the board (mps2-an386: the MPS2 with the AN386 Cortex-M4
# image); the program reports through semihosting and its exit status becomes QEMU's, so
# a plain add_test(NAME x COMMAND image) runs it and a failure fails the test.
set(CMAKE_CROSSCOMPILING_EMULATOR
    qemu-system-arm -M ${ALOFT_QEMU_MACHINE} -nographic -monitor none
    -semihosting-config enable=on,target=native -kernel)

# Target libraries and headers from the cross toolchain only; CMake packages may come from
# the host, which is right for header-only ones (Eigen).
set(CMAKE_FIND_ROOT_PATH /usr/lib/arm-none-eabi)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
