# STM32F405 flight controllers (Cortex-M4F), the `stm32f405` preset: the bare-metal
# compiler of arm-none-eabi-gcc.cmake with the stm32f405 port (port/stm32f405/), images
# run under QEMU's netduinoplus2, the STM32F405 board QEMU models.
set(ALOFT_PORT "stm32f405" CACHE STRING "Platform port: host, cortex_m, stm32f405 or linux_arm")
set(ALOFT_QEMU_MACHINE netduinoplus2)
include(${CMAKE_CURRENT_LIST_DIR}/arm-none-eabi-gcc.cmake)
