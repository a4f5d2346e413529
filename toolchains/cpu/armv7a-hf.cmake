# CPU part of the Linux-on-ARM toolchain: the Debian armhf baseline (ARMv7-A, Thumb-2,
# VFPv3-D16, hard-float calling convention), so the binaries run on any armhf board and
# under qemu-arm's default CPU.
set(ALOFT_CPU_FLAGS "-march=armv7-a -mthumb -mfpu=vfpv3-d16 -mfloat-abi=hard")
