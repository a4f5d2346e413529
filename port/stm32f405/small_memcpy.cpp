// memcpy for the STM32F405 images, in place of newlib-nano's: this toolchain builds that
// one as the ARMv7-M copy unrolled for speed, 308 B of flash. The flight image calls it at
// start-up only: for the .data image (a copy loop GCC turns into the call) and for the
// pipeline's default settings (a block over 64 B, which GCC copies by call where it
// optimises for size); never on the per-sample path (footprint.json's
// instructions_per_sample would count it). A byte loop serves it for 284 B of flash less.
// Compiled with -Os (at -O3 GCC vectorised the loop into 112 B) and with
// -fno-tree-loop-distribute-patterns, without which GCC would turn the loop back into a
// call to memcpy, itself (../CMakeLists.txt).
#include <cstddef>
#include <cstring>

extern "C" void* memcpy(void* __restrict dst, const void* __restrict src, std::size_t n) {
  auto* to = static_cast<unsigned char*>(dst);
  const auto* from = static_cast<const unsigned char*>(src);
  while (n-- != 0) *to++ = *from++;
  return dst;
}
