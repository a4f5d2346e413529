# CPU part of the bare-metal toolchain: Cortex-M4 with its single-precision FPU, hard-float
# calling convention. Only float arithmetic runs in hardware here; any double becomes a
# soft-float library call (__aeabi_d*), which the firmware checks forbid.
set(ALOFT_CPU_FLAGS "-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard")
