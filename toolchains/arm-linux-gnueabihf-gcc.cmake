# Linux on 32-bit ARM with hard float (Debian g++-arm-linux-gnueabihf), compiler part; CPU
# flags in cpu/<ALOFT_CPU>.cmake. Used by the `armhf` preset: test programs run under
# qemu-user through CMAKE_CROSSCOMPILING_EMULATOR (ETL style), so plain add_test() works.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)

set(ALOFT_CPU "armv7a-hf" CACHE STRING "CPU flags file in toolchains/cpu/")
set(ALOFT_PORT "linux_arm" CACHE STRING "Platform port: host, cortex_m or linux_arm")
include(${CMAKE_CURRENT_LIST_DIR}/cpu/${ALOFT_CPU}.cmake)

set(ALOFT_SYSROOT /usr/arm-linux-gnueabihf)
set(CMAKE_C_COMPILER arm-linux-gnueabihf-gcc)
set(CMAKE_CXX_COMPILER arm-linux-gnueabihf-g++)
set(CMAKE_C_FLAGS_INIT "${ALOFT_CPU_FLAGS}")
set(CMAKE_CXX_FLAGS_INIT "${ALOFT_CPU_FLAGS}")

# -L: where qemu-arm finds the ARM dynamic loader and shared libraries.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-arm -L ${ALOFT_SYSROOT})

set(CMAKE_FIND_ROOT_PATH ${ALOFT_SYSROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
# Header-only host packages (Eigen, Catch2) serve the target as they are. Catch2's names
# /usr/include, which Debian's cross compiler already searches last, after the target's
# own headers, so CMake drops it as an implicit directory and the order stays right.
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
